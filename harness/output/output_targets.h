#pragma once
/// The checks every command runs on the files and folders it will write, before it starts work.
///
/// One rule set for every output of every command (docs/stability.md, "Hostile input: outputs"):
/// - an existing file target must be a regular file (a folder, device, FIFO or socket is refused)
///   that shatterbench wrote, or empty (own_output.h): a file of the user's is never replaced;
/// - an existing folder target must be empty or marked as shatterbench's own (output_folder.h);
/// - two outputs of one command must not resolve to the same file (after symbolic links, `..` and
///   hard links), nor a file lie inside a folder output;
/// - nothing is written inside a baseline folder unless it is the baseline update itself, and no
///   folder output may hold a baseline folder.
/// The writers check the first two again under the folder lock, when they write.

#include "algorithms/core/result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace shatter {

/// One output of a command: the option that named it, where it goes, what it is.
struct OutputTarget {
  std::string flag;                ///< "--json", "--json (CSV beside it)", "--junit", "--out", ...
  std::filesystem::path path;      ///< as the user named it
  bool folder = false;             ///< a folder output (output_folder.h) rather than one file
  bool baseline_update = false;    ///< the one output allowed inside a baseline folder
};

/// The baseline folders a command protects: `results/baselines` (relative to the working folder),
/// plus `extra` when not empty (grid's --baseline-dir).
std::vector<std::filesystem::path> baseline_folders(const std::filesystem::path& extra = {});

/// Error when `path` (a folder shatterbench adds files to, such as the pre-fracture cache) lies inside
/// one of `protected_folders`; `flag` names the option.
Status check_outside_baselines(const std::string& flag, const std::filesystem::path& path,
                               const std::vector<std::filesystem::path>& protected_folders = baseline_folders());

/// Checks `targets` against the rules above, and that none is one of `inputs` (the files the command
/// reads: a file output that is an input, or a folder output that holds one, is refused); the error
/// names the flag, the path and the rule. Empty paths are skipped (an output that was not asked for).
Status check_outputs(const std::vector<OutputTarget>& targets,
                     const std::vector<std::filesystem::path>& protected_folders = baseline_folders(),
                     const std::vector<std::filesystem::path>& inputs = {});

}  // namespace shatter
