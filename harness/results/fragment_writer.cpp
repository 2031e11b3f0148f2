#include "harness/results/fragment_writer.h"

#include "algorithms/core/mesh_io.h"
#include "harness/results/atomic_file.h"

#include <fmt/core.h>

#include <regex>
#include <system_error>
#include <vector>

namespace shatter {
namespace fs = std::filesystem;

namespace {

bool is_fragment_file(const fs::path& p) {
  static const std::regex pattern(R"(fragment_\d{3,}\.obj)");
  return std::regex_match(p.filename().string(), pattern);
}

}  // namespace

Status write_fragments(const fs::path& dir, std::span<const Fragment> fragments) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return Error{dir.string() + ": exists and is not a folder"};
  const fs::path temp = temporary_beside(dir);
  if (!fs::create_directories(temp, ec)) return Error{temp.string() + ": cannot create folder: " + ec.message()};
  const auto give_up = [&](Error e) {
    fs::remove_all(temp, ec);
    return e;
  };
  std::vector<fs::path> names;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    names.emplace_back(fmt::format("fragment_{:03}.obj", i));
    if (Status s = write_obj(fragments[i].mesh, temp / names.back()); !s) return give_up(s.error());
  }
  if (!fs::exists(dir, ec)) {
    fs::rename(temp, dir, ec);
    if (ec) return give_up(Error{dir.string() + ": cannot move results into place: " + ec.message()});
    return {};
  }
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (is_fragment_file(e.path())) fs::remove(e.path(), ec);
  for (const fs::path& name : names) {
    fs::rename(temp / name, dir / name, ec);
    if (ec) return give_up(Error{(dir / name).string() + ": cannot move into place: " + ec.message()});
  }
  fs::remove_all(temp, ec);
  return {};
}

}  // namespace shatter
