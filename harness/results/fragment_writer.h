#pragma once
/// Writing fragments to a folder without ever leaving a partial result behind.

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"

#include <filesystem>
#include <span>
#include <string>

namespace shatter {

/// Writes the folder `DIR` holding `fragment_NNN.obj` (NNN from 000, at least three digits) and, when
/// the fragments carry material slots, the one library `fragments.mtl` they all name, and
/// `fragments.glb` (write_fragments_glb.h: every fragment as a node at its centroid, with its
/// attributes and materials; written for fragments with or without attributes); whole or
/// not at all (harness/output/output_folder.h): DIR must be absent, empty or an earlier output of
/// shatterbench, which is replaced as a whole. On error nothing in DIR changes.
///
/// Textures travel with the fragments: an image a material names as a file (relative to
/// `asset_folder`, the folder of the mesh file that was read) is copied to `DIR/textures/` and both
/// `fragments.mtl` and `fragments.glb` name the copy; an image embedded in the input is written to
/// `DIR/textures/` for the MTL and stays embedded in the glTF binary. A named image that is missing,
/// outside `asset_folder` (asset_reference.h) or larger than kMaxTextureBytes is an error naming the
/// material and the file, and nothing is written.
///
/// `summary`, when not empty, is written as `DIR/fracture.json`: what made the fragments (the fracture
/// command's JSON with `kind` "fracture"; docs/results.md, "Fragments folder"), so that `report` can
/// label and group the folder.
Status write_fragments(const std::filesystem::path& dir, std::span<const Fragment> fragments,
                       const std::filesystem::path& asset_folder = {}, const std::string& summary = {});

/// The files of write_fragments written into `dir`, an existing empty folder that the caller makes
/// whole or removes (a staging folder of write_folder_atomically); for outputs of several folders.
Status write_fragment_files(const std::filesystem::path& dir, std::span<const Fragment> fragments,
                            const std::filesystem::path& asset_folder, const std::string& summary);

/// `name` with every character but letters, digits, '-', '_' and '.' made '_', never starting with
/// '.', at most 100 characters: a file name that means the same on every system (never a path).
std::string safe_file_name(const std::string& name);

/// The name of the summary file in a fragments folder.
inline constexpr const char* kFragmentsSummaryFile = "fracture.json";

}  // namespace shatter
