#pragma once
/// The fragments folders `report` shows in 3D: a folder written by `fracture --out` or one row of
/// `table --out` (docs/results.md, "Fragments folder": `fracture.json` saying what made it and
/// `fragments.glb` holding the fragments), read and checked before the page embeds them.
///
/// Design note: the page embeds the folder's own glTF binary rather than a copy made for the page, so
/// what the user sees is the file a game would load; the binary is checked here (header, chunk
/// lengths, every buffer view and accessor inside the binary chunk, index counts) so that a truncated
/// or altered file is refused with one line instead of drawing half a scene. Images the binary names
/// by a relative URI are read as references inside the folder (asset_reference.h) and embedded beside
/// it, since the page fetches nothing.

#include "algorithms/core/result.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace shatter {

/// One fragments folder, checked.
struct ReportFragments {
  std::string folder;                 ///< the folder as given, or as found below a given folder
  nlohmann::ordered_json summary;     ///< fracture.json as read
  std::string algorithm;              ///< summary.algorithm
  std::string mesh;                   ///< the file name of summary.input.file
  std::int64_t seed = 0;              ///< summary.seed
  std::int64_t requested = 0;         ///< summary.requested
  std::string glb;                    ///< the bytes of fragments.glb
  std::vector<std::pair<std::string, std::string>> images;  ///< (URI, bytes) of every image named by URI
  std::size_t fragments = 0;          ///< nodes of the binary (one per fragment)
  std::size_t triangles = 0;          ///< triangles over every primitive
};

/// The fragments folder `folder` (holding fracture.json), checked; errors name the folder and the file.
Result<ReportFragments> read_fragments_folder(const std::filesystem::path& folder);

/// Every fragments folder at or below `folder` (at most kMaxFragmentsFolderDepth levels down; symbolic
/// links are not followed), in path order; an error when there is none or when one is invalid.
Result<std::vector<ReportFragments>> find_fragments_folders(const std::filesystem::path& folder);

/// How deep below a given folder `report` looks for fragments folders (`table --out` nests three).
inline constexpr int kMaxFragmentsFolderDepth = 3;

}  // namespace shatter
