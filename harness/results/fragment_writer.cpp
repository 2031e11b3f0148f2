#include "harness/results/fragment_writer.h"

#include "algorithms/assets/write_fragments_glb.h"
#include "algorithms/core/material_library.h"
#include "algorithms/core/asset_reference.h"
#include "algorithms/core/bounded_read.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_text.h"
#include "harness/limits.h"
#include "harness/output/output_folder.h"

#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <set>
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

/// The textures of `slots` written into `staging/textures/`, and each textured slot's name mapped to
/// the copy's path relative to the output folder (see write_fragments).
Result<std::map<std::string, std::string>> copy_textures(const std::vector<MaterialSlot>& slots,
                                                         const fs::path& asset_folder, const fs::path& staging) {
  std::map<std::string, std::string> copied;   // slot name -> "textures/<file>"
  std::map<std::string, std::string> by_source;  // a file named by several materials is copied once
  std::set<std::string> taken;
  const auto fresh_name = [&](const std::string& wanted) {
    std::string name = safe_file_name(wanted);
    for (int k = 2; taken.contains(name); ++k) name = fmt::format("{}_{}", k, safe_file_name(wanted));
    taken.insert(name);
    return "textures/" + name;
  };
  const fs::path folder = asset_folder.empty() ? fs::path(".") : asset_folder;
  for (const MaterialSlot& slot : slots) {
    std::string bytes;
    std::string target;
    if (slot.base_color_image) {
      const bool jpeg = slot.base_color_image->mime_type == "image/jpeg";
      target = fresh_name(slot.name + (jpeg ? ".jpg" : ".png"));
      bytes.assign(slot.base_color_image->bytes.begin(), slot.base_color_image->bytes.end());
    } else if (!slot.base_color_texture.empty()) {
      if (const auto seen = by_source.find(slot.base_color_texture); seen != by_source.end()) {
        copied[slot.name] = seen->second;
        continue;
      }
      const std::string what = "texture of material '" + slot.name + "'";
      Result<fs::path> file = resolve_reference(folder, slot.base_color_texture, kMaxTextureBytes, what);
      if (!file) return file.error();
      Result<std::string> read = read_file_bounded(*file, kMaxTextureBytes, what);
      if (!read) return read.error();
      bytes = std::move(*read);
      target = fresh_name(fs::path(slot.base_color_texture).filename().string());
      by_source[slot.base_color_texture] = target;
    } else {
      continue;
    }
    if (copied.empty()) {
      std::error_code ec;
      fs::create_directory(staging / "textures", ec);
      if (ec) return Error{(staging / "textures").string() + ": cannot create: " + ec.message()};
    }
    if (Status s = write_file_bytes(bytes, staging / target); !s) return s.error();
    copied[slot.name] = target;
  }
  return copied;
}

}  // namespace

std::string safe_file_name(const std::string& name) {
  std::string out;
  for (const char c : name.substr(0, 100)) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
    out += plain ? c : '_';
  }
  if (out.empty() || out.front() == '.') out.insert(out.begin(), '_');
  return out;
}

Status write_fragments(const fs::path& dir, std::span<const Fragment> fragments, const fs::path& asset_folder,
                       const std::string& summary) {
  return write_folder_atomically(dir, [&](const fs::path& staging) -> Status {
    return write_fragment_files(staging, fragments, asset_folder, summary);
  });
}

Status write_fragment_files(const fs::path& staging, std::span<const Fragment> fragments, const fs::path& asset_folder,
                            const std::string& summary) {
  {
    std::vector<MaterialSlot> slots = shared_slots(fragments);
    Result<std::map<std::string, std::string>> textures = copy_textures(slots, asset_folder, staging);
    if (!textures) return textures.error();
    // Every file texture now names its copy; an embedded image stays embedded in the glTF binary.
    std::vector<Fragment> renamed;
    for (MaterialSlot& slot : slots)
      if (const auto t = textures->find(slot.name); t != textures->end()) slot.base_color_texture = t->second;
    if (std::any_of(slots.begin(), slots.end(), [](const MaterialSlot& s) { return !s.base_color_image && !s.base_color_texture.empty(); })) {
      renamed.assign(fragments.begin(), fragments.end());
      for (Fragment& f : renamed)
        for (MaterialSlot& slot : f.mesh.attributes.slots)
          if (const auto t = textures->find(slot.name); t != textures->end() && !slot.base_color_image)
            slot.base_color_texture = t->second;
      fragments = renamed;
    }
    const std::string library = slots.empty() ? std::string() : "fragments.mtl";
    if (!slots.empty())
      if (Status s = write_mtl(slots, staging / library); !s) return s;
    for (std::size_t i = 0; i < fragments.size(); ++i)
      if (Status s = write_obj(fragments[i].mesh, staging / fmt::format("fragment_{:03}.obj", i), library); !s) return s;
    if (!summary.empty())
      if (Status s = write_file_bytes(summary, staging / kFragmentsSummaryFile); !s) return s;
    // Always, attributes or not: one file a game engine or viewer opens with every fragment placed.
    return write_fragments_glb(staging / "fragments.glb", fragments);
  }
}

}  // namespace shatter
