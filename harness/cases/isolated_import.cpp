#include "harness/cases/isolated_import.h"

#include "algorithms/assets/mesh_codec.h"
#include "algorithms/assets/read_asset.h"
#include "harness/limits.h"
#include "harness/process/isolated_run.h"
#include "harness/process/resource_limits.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace shatter {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  if (!ext.empty() && ext.front() == '.') ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

Result<Mesh> read_asset_isolated(const std::filesystem::path& path, const MeshReadLimits& limits,
                                 const ImportLimits& import) {
  const std::string ext = lower_extension(path);
  if (ext == "off" || ext == "obj") return read_asset(path, limits);
  const std::uint64_t memory = import.memory_bytes > 0 ? import.memory_bytes : kMaxImportMemoryBytes;
  const double time_s = import.time_s > 0.0 ? import.time_s
                                            : kMaxImportSeconds * (sanitized_build() ? kSanitizerSlowdown : 1.0);
  // The child answers 'M' and the encoded mesh, or 'E' and the error's line.
  const IsolatedRun run = run_isolated(
      [&]() -> std::string {
        if (!limit_this_process(memory, time_s)) return "E" + path.string() + ": cannot limit the importer's resources";
        Result<Mesh> mesh = read_asset(path, limits);
        return mesh ? "M" + encode_mesh(*mesh) : "E" + mesh.error().message;
      },
      time_s);
  const std::string file = path.string();
  switch (run.end) {
    case IsolatedRun::End::timed_out:
      return Error{fmt::format("{}: the importer (assimp) took longer than the limit of {:g} s", file, time_s)};
    case IsolatedRun::End::crashed:
      return Error{fmt::format("{}: the importer (assimp) failed on this file ({}; its memory limit is {} GiB)", file,
                               run.detail, memory >> 30)};
    case IsolatedRun::End::finished: break;
  }
  if (run.output.empty()) return Error{file + ": the importer (assimp) gave no answer"};
  if (run.output.front() == 'E') return Error{run.output.substr(1, 2000)};
  if (run.output.front() != 'M') return Error{file + ": the importer (assimp) gave an answer that is not a mesh"};
  return decode_mesh(run.output.substr(1), file);
}

}  // namespace shatter
