#include "algorithms/core/material_library.h"

#include "algorithms/core/bounded_read.h"
#include "algorithms/core/mesh_text.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>
#include <unordered_map>

namespace shatter {
Result<std::vector<MaterialSlot>> read_mtl(const std::filesystem::path& path, const MeshReadLimits& limits) {
  const std::string file = path.string();
  Result<std::string> text = read_file_bounded(path, limits.max_file_bytes, "material library");
  if (!text) return text.error();
  TokenLines lines(*text);
  const auto fail = [&](const std::string& what) { return Error{file + ":" + std::to_string(lines.line()) + ": " + what}; };

  std::vector<MaterialSlot> slots;
  std::unordered_map<std::string, std::size_t> index;  // name -> its slot (linear in the definitions)
  std::size_t current = 0;                              // the slot the statements after `newmtl` set
  while (lines.next()) {
    const auto& tokens = lines.tokens();
    const std::string_view key = tokens[0];
    const auto numbers = [&](std::size_t count_min, std::size_t count_max) -> Result<std::vector<double>> {
      const std::size_t n = tokens.size() - 1;
      if (n < count_min || n > count_max)
        return fail("'" + std::string(key) + "' has " + std::to_string(n) + " numbers, expected " +
                    std::to_string(count_min) + (count_max != count_min ? " to " + std::to_string(count_max) : ""));
      std::vector<double> values;
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        const Result<double> x = parse_finite_double(tokens[i]);
        if (!x) return fail("'" + std::string(key) + "': " + x.error().message);
        values.push_back(std::clamp(*x, 0.0, 1.0));
      }
      return values;
    };
    if (key == "newmtl") {
      if (tokens.size() < 2) return fail("'newmtl' without a material name");
      MaterialSlot slot;
      slot.name = joined_tokens(tokens, 1);
      const auto [found, added] = index.try_emplace(slot.name, slots.size());
      if (added) slots.push_back(std::move(slot));
      else slots[found->second] = std::move(slot);  // the later definition wins, in the first one's place
      current = found->second;
      continue;
    }
    const bool known = key == "Kd" || key == "d" || key == "Tr" || key == "map_Kd";
    if (!known) continue;
    if (slots.empty()) return fail("'" + std::string(key) + "' before the first 'newmtl'");
    MaterialSlot& slot = slots[current];
    if (key == "Kd") {
      Result<std::vector<double>> c = numbers(1, 3);
      if (!c) return c.error();
      for (std::size_t i = 0; i < 3; ++i) slot.base_color[i] = (*c)[c->size() == 1 ? 0 : i];
    } else if (key == "d" || key == "Tr") {
      Result<std::vector<double>> a = numbers(1, 1);
      if (!a) return a.error();
      slot.base_color[3] = key == "d" ? (*a)[0] : 1.0 - (*a)[0];
    } else {
      if (tokens.size() < 2) return fail("'map_Kd' without a file");
      // Options (-s, -o, -bm, ...) come first: then the file is the last token; without options the
      // whole rest is the file, spaces included.
      slot.base_color_texture = tokens[1].starts_with("-") ? std::string(tokens.back()) : joined_tokens(tokens, 1);
    }
  }
  return slots;
}

Status write_mtl(std::span<const MaterialSlot> slots, const std::filesystem::path& path) {
  std::string out = "# shatterbench materials\n";
  char buffer[160];
  for (const MaterialSlot& s : slots) {
    out += "newmtl " + s.name + "\n";
    const auto& c = s.base_color;
    int n = std::snprintf(buffer, sizeof buffer, "Kd %.17g %.17g %.17g\nd %.17g\n", c[0], c[1], c[2], c[3]);
    out.append(buffer, static_cast<std::size_t>(n));
    if (!s.base_color_texture.empty()) out += "map_Kd " + s.base_color_texture + "\n";
  }
  return write_file_bytes(out, path);
}

}  // namespace shatter
