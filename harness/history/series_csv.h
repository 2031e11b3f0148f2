#pragma once
/// A plain series from a CSV file, for `history changes --csv`: one `commit,value` line per point in
/// order, an optional header line (`commit,value`), blank lines ignored. Any series can so be checked
/// by hand against the change points the history finds.

#include "algorithms/core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shatter {

/// The most bytes a series file may hold (10 MiB: about half a million points).
inline constexpr std::uint64_t kMaxSeriesCsvBytes = std::uint64_t{10} << 20;

/// Labelled points of one series, in order.
struct LabelledSeries {
  std::vector<std::string> labels;  ///< the commit (or any label) of each point
  std::vector<double> values;
};

/// The series in `path`, or an error "<path>:<line>: <what is wrong>" (a line without exactly two
/// fields, an empty label, a value that is not a finite number) or naming the file when it cannot be
/// read or holds no point.
Result<LabelledSeries> read_series_csv(const std::filesystem::path& path);

}  // namespace shatter
