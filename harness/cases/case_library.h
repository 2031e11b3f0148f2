#pragma once
/// The built-in cases (cases/*.json) by name, and case lookup for the CLI: `--case FILE|NAME`.
///
/// Search order for a name: `$SHATTER_CASE_DIR`, `<folder of the running executable>/../share/
/// shatterbench/cases` (an installed shatterbench), `<folder of the running executable>/../../cases`
/// (the binary is build/bin/shatterbench), the install prefix's case folder as configured
/// (SHATTER_INSTALLED_CASE_DIR: a program of a user's own, linked with the installed harness, finds
/// the installed cases wherever it runs), `SHATTER_SOURCE_DIR/cases` when the build defines that
/// macro, and last `cases/` under the current directory. The first folder holding `<name>.json` wins.

#include "algorithms/core/result.h"
#include "harness/cases/case.h"

#include <filesystem>
#include <string>
#include <vector>

namespace shatter {

/// A case file found in a search folder.
struct BuiltinCase {
  std::string name;                  ///< file stem, what find_case() accepts
  std::string description;           ///< the file's "description" (one line; may be empty)
  std::filesystem::path path;        ///< the JSON file
};

/// The existing folders searched for built-in cases, in search order, without repeats.
std::vector<std::filesystem::path> case_search_dirs();

/// Loads `name_or_path`: an existing file is loaded as is; otherwise `<name>.json` from the first
/// search folder that has it. An unknown name is an error listing the built-in names.
Result<Case> find_case(const std::string& name_or_path);

/// Every case in the search folders (a name found twice: the first folder wins), sorted by name.
/// Only the description is read, so a broken case still lists (its description says so).
std::vector<BuiltinCase> list_builtin_cases();

}  // namespace shatter
