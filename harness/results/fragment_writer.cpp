#include "harness/results/fragment_writer.h"

#include "algorithms/core/mesh_io.h"
#include "harness/output/output_folder.h"

#include <fmt/core.h>


namespace shatter {
namespace fs = std::filesystem;

Status write_fragments(const fs::path& dir, std::span<const Fragment> fragments) {
  return write_folder_atomically(dir, [&](const fs::path& staging) -> Status {
    for (std::size_t i = 0; i < fragments.size(); ++i)
      if (Status s = write_obj(fragments[i].mesh, staging / fmt::format("fragment_{:03}.obj", i)); !s) return s;
    return {};
  });
}

}  // namespace shatter
