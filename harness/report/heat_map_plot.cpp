#include "harness/report/heat_map_plot.h"

#include "harness/report/gnuplot_runner.h"
#include "harness/report/gnuplot_text.h"
#include "harness/output/atomic_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <set>
#include <vector>

namespace shatter {

Result<std::string> plot_heat_map(const ReportGrid& grid, const std::filesystem::path& folder, const std::string& stem) {
  std::set<int> row_set, column_set;
  for (const ReportCell& c : grid.cells) {
    row_set.insert(c.prefracture);
    column_set.insert(c.runtime);
  }
  const std::vector<int> rows(row_set.begin(), row_set.end()), columns(column_set.begin(), column_set.end());
  const auto index = [](const std::vector<int>& v, int x) {
    return static_cast<int>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
  };
  double largest = 0.0;
  for (const ReportCell& c : grid.cells)
    if (c.failed.empty()) largest = std::max(largest, c.worst_frame_ms);
  const double b = grid.budget_ms;
  const double top = std::max(1.5 * b, largest);

  // x y value "label" over (0 within, 1 over, 2 failed); a cell missing from the file stays blank.
  std::string data = "# runtime_index prefracture_index worst_frame_ms label over_budget\n";
  std::string frames;
  for (const ReportCell& c : grid.cells) {
    const int x = index(columns, c.runtime), y = index(rows, c.prefracture);
    if (!c.failed.empty()) {  // no figure: a blank box, framed, labelled "failed"
      data += fmt::format("{} {} NaN \"failed\" 2\n", x, y);
      frames +=
          fmt::format("set object rect from {}, {} to {}, {} front fillstyle empty border lc rgb \"black\" lw 3\n",
                      x - 0.5, y - 0.5, x + 0.5, y + 0.5);
      continue;
    }
    const std::string label = c.within_budget ? fmt::format("{:.2f}", c.worst_frame_ms)
                                              : fmt::format("{:.2f} !", c.worst_frame_ms);
    data += fmt::format("{} {} {:.6g} \"{}\" {}\n", x, y, c.worst_frame_ms, label, c.within_budget ? 0 : 1);
    if (!c.within_budget)
      frames += fmt::format("set object rect from {}, {} to {}, {} front fillstyle empty border lc rgb \"black\" lw 3\n",
                            x - 0.5, y - 0.5, x + 0.5, y + 0.5);
  }
  std::string xtics, ytics;
  for (std::size_t i = 0; i < columns.size(); ++i) xtics += fmt::format("{}\"{}\" {}", i ? ", " : "", columns[i], i);
  for (std::size_t i = 0; i < rows.size(); ++i) ytics += fmt::format("{}\"{}\" {}", i ? ", " : "", rows[i], i);
  int over = 0, failed = 0;
  for (const ReportCell& c : grid.cells) {
    over += c.failed.empty() && !c.within_budget ? 1 : 0;
    failed += c.failed.empty() ? 0 : 1;
  }
  const std::string failed_note = failed > 0 ? fmt::format(", {} failed (blank, framed)", failed) : std::string();

  const int width = std::max(640, 110 * static_cast<int>(columns.size()) + 260);
  const int height = std::max(420, 48 * static_cast<int>(rows.size()) + 170);
  const std::string image = stem + ".png";
  // The case name is text from a file: data, read into a variable (gnuplot_text.h).
  GnuplotStrings strings;
  const std::string case_title = strings.add(grid.case_name);
  std::string script;
  script += fmt::format("set terminal pngcairo noenhanced size {},{} font \"Sans,10\"\n", width, height);
  script += fmt::format("set output \"{}\"\n", image);
  script += strings.load(stem + ".txt");
  script += fmt::format(
      "set title {} . \": worst frame per cell (ms), budget {:g} ms\\n{} of {} cells over the budget (red, framed, !){}\"\n",
      case_title, b, over, grid.cells.size(), failed_note);
  script += "set xlabel \"runtime fragments\"\nset ylabel \"pre-fracture fragments\"\n";
  script += fmt::format("set xrange [-0.5:{}]\nset yrange [-0.5:{}]\n", columns.size() - 0.5, rows.size() - 0.5);
  script += fmt::format("set xtics ({}) scale 0\nset ytics ({}) scale 0\n", xtics, ytics);
  script += fmt::format("set cbrange [0:{:.6g}]\nset cblabel \"worst frame (ms)\"\nset rmargin 14\n", top);
  script += fmt::format("set cbtics add (\"budget {:g}\" {:.6g})\n", b, b);
  script += fmt::format(
      "set palette defined (0 \"#1a9850\", {0:.6g} \"#a6d96a\", {1:.6g} \"#fee08b\", {2:.6g} \"#fdae61\", {2:.6g} \"#e34a33\", {3:.6g} \"#b30000\")\n",
      0.4 * b, 0.75 * b, b, top);
  script += "unset key\nset tics out\nset border lw 1\n";
  script += frames;
  script += fmt::format(
      "plot \"{0}.dat\" using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder lc palette, \\\n"
      "     \"{0}.dat\" using 1:2:($5 == 0 ? stringcolumn(4) : \"\") with labels font \"Sans,10\" tc rgb \"black\", \\\n"
      "     \"{0}.dat\" using 1:2:($5 == 1 ? stringcolumn(4) : \"\") with labels font \"Sans Bold,10\" tc rgb \"white\", \\\n"
      "     \"{0}.dat\" using 1:2:($5 == 2 ? stringcolumn(4) : \"\") with labels font \"Sans Bold,10\" tc rgb \"black\"\n",
      stem);
  if (Status s = write_file_atomically(folder / (stem + ".txt"), strings.data()); !s) return s.error();
  if (Status s = write_file_atomically(folder / (stem + ".dat"), data); !s) return s.error();
  if (Status s = write_file_atomically(folder / (stem + ".gp"), script); !s) return s.error();
  if (Status s = run_gnuplot(folder, stem + ".gp"); !s) return s.error();
  return image;
}

}  // namespace shatter
