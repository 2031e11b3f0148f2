#include "harness/cases/isolated_import.h"

#include "algorithms/assets/mesh_codec.h"
#include "algorithms/assets/read_asset.h"
#include "harness/limits.h"
#include "harness/process/isolated_run.h"

#include <fmt/core.h>

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <string>

// AddressSanitizer and ThreadSanitizer reserve terabytes of address space for their shadow memory:
// under them the child's address space is not limited (GCC says so by a macro, clang by a feature).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SHATTER_UNLIMITED_ADDRESS_SPACE 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define SHATTER_UNLIMITED_ADDRESS_SPACE 1
#endif
#endif

namespace shatter {
namespace {

/// Sets the child's limits; false when the kernel refuses one.
bool limit_child(std::uint64_t memory_bytes, double time_s) {
  const auto set = [](int resource, rlim_t value) {
    const rlimit r{value, value};
    return ::setrlimit(resource, &r) == 0;
  };
  bool ok = set(RLIMIT_FSIZE, 0) && set(RLIMIT_CORE, 0);
  ok = ok && set(RLIMIT_CPU, static_cast<rlim_t>(time_s) + 1);
#if !defined(SHATTER_UNLIMITED_ADDRESS_SPACE)
  ok = ok && set(RLIMIT_AS, static_cast<rlim_t>(memory_bytes));
#else
  (void)memory_bytes;
#endif
  return ok;
}

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
  const double time_s = import.time_s > 0.0 ? import.time_s : kMaxImportSeconds;
  // The child answers 'M' and the encoded mesh, or 'E' and the error's line.
  const IsolatedRun run = run_isolated(
      [&]() -> std::string {
        if (!limit_child(memory, time_s)) return "E" + path.string() + ": cannot limit the importer's resources";
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
