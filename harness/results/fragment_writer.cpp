#include "harness/results/fragment_writer.h"

#include "algorithms/assets/write_fragments_glb.h"
#include "algorithms/core/material_library.h"
#include "algorithms/core/mesh_io.h"
#include "harness/output/output_folder.h"

#include <fmt/core.h>

#include <algorithm>
#include <vector>

namespace shatter {
namespace fs = std::filesystem;
namespace {

/// The material slots of all fragments, one per name (fragments cut from one mesh share their slots).
std::vector<MaterialSlot> shared_slots(std::span<const Fragment> fragments) {
  std::vector<MaterialSlot> slots;
  for (const Fragment& f : fragments)
    for (const MaterialSlot& s : f.mesh.attributes.slots)
      if (std::none_of(slots.begin(), slots.end(), [&](const MaterialSlot& t) { return t.name == s.name; }))
        slots.push_back(s);
  return slots;
}

}  // namespace

Status write_fragments(const fs::path& dir, std::span<const Fragment> fragments) {
  return write_folder_atomically(dir, [&](const fs::path& staging) -> Status {
    const std::vector<MaterialSlot> slots = shared_slots(fragments);
    const std::string library = slots.empty() ? std::string() : "fragments.mtl";
    if (!slots.empty())
      if (Status s = write_mtl(slots, staging / library); !s) return s;
    for (std::size_t i = 0; i < fragments.size(); ++i)
      if (Status s = write_obj(fragments[i].mesh, staging / fmt::format("fragment_{:03}.obj", i), library); !s) return s;
    // Always, attributes or not: one file a game engine or viewer opens with every fragment placed.
    return write_fragments_glb(staging / "fragments.glb", fragments);
  });
}

}  // namespace shatter
