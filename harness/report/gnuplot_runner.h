#pragma once
/// Running gnuplot (Debian package gnuplot-nox, scripts/install-deps) on a script in a folder.

#include "algorithms/core/result.h"

#include <filesystem>
#include <string>

namespace shatter {

/// The gnuplot executable: $SHATTER_GNUPLOT when set, else "gnuplot" from PATH.
std::string gnuplot_program();

/// Runs `gnuplot SCRIPT` with `folder` as the working directory (the script names its data files and
/// outputs relative to it). Error when gnuplot cannot be started or exits non-zero; the message holds
/// the first line gnuplot printed on stderr.
Status run_gnuplot(const std::filesystem::path& folder, const std::string& script);

}  // namespace shatter
