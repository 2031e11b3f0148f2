#include "harness/report/stage_bars_plot.h"

#include "harness/report/gnuplot_runner.h"
#include "harness/report/gnuplot_text.h"
#include "harness/output/atomic_file.h"

#include <fmt/core.h>

#include <vector>

namespace shatter {

Result<std::string> plot_stage_bars(const ReportCell& cell, const std::string& case_name, int frames,
                                    const std::filesystem::path& folder, const std::string& stem) {
  if (cell.stages_ms.empty()) return Error{"cell " + std::to_string(cell.prefracture) + " x " +
                                           std::to_string(cell.runtime) + ": stages_ms is empty"};
  // Stages that took no time in any bar (skipped or not needed) are left out of the chart.
  StageTimes stages;
  for (const auto& [stage, ms] : cell.stages_ms) {
    bool used = ms > 0.0;
    for (const StageTimes& run : cell.sample_stages_ms)
      for (const auto& [name, value] : run) used = used || (name == stage && value > 0.0);
    if (used) stages.emplace_back(stage, ms);
  }
  if (stages.empty()) stages = cell.stages_ms;
  // One row per bar, one column per stage (the median's stage order); a stage missing from a
  // repetition counts 0.
  std::string data = "# bar, then one column per stage (names in the .txt file beside this one)\n";
  const auto row = [&](const std::string& label, const StageTimes& times) {
    data += "\"" + label + "\"";
    for (const auto& [stage, ignored] : stages) {
      double ms = 0.0;
      for (const auto& [name, value] : times)
        if (name == stage) ms = value;
      data += fmt::format(" {:.6g}", ms);
    }
    data += "\n";
  };
  row("median", cell.stages_ms);
  for (std::size_t k = 0; k < cell.sample_stages_ms.size(); ++k) row(fmt::format("run {}", k + 1), cell.sample_stages_ms[k]);

  const std::string image = stem + ".png";
  const std::string over = frames > 0 ? fmt::format("summed over {} frames", frames) : "summed over the frames";
  // Names from the results file (case, fracturer, stress model, stages) are data (gnuplot_text.h).
  GnuplotStrings strings;
  const std::string title = strings.add(fmt::format("{} cell {} x {} ({}{}): time per stage, {}", case_name,
                                                    cell.prefracture, cell.runtime, cell.fracturer,
                                                    cell.stress.empty() ? "" : ", " + cell.stress, over));
  std::vector<std::string> legend;
  for (const auto& [stage, ms] : stages) legend.push_back(strings.add(fmt::format("{} ({:.3g} ms)", stage, ms)));
  std::string script;
  script += "set terminal pngcairo noenhanced size 900,520 font \"Sans,10\"\n";
  script += fmt::format("set output \"{}\"\n", image);
  script += strings.load(stem + ".txt");
  script += fmt::format("set title {}\n", title);
  script += "set ylabel \"time (ms)\"\nset yrange [0:*]\nset grid ytics\n";
  script += "set style data histograms\nset style histogram rowstacked\nset style fill solid 0.85 border -1\n";
  script += "set boxwidth 0.6\nset key outside right top vertical title \"stage (median)\"\nset xtics scale 0\n";
  script += "set linetype 1 lc rgb \"#4e79a7\"\nset linetype 2 lc rgb \"#f28e2b\"\nset linetype 3 lc rgb \"#e15759\"\n"
            "set linetype 4 lc rgb \"#76b7b2\"\nset linetype 5 lc rgb \"#59a14f\"\nset linetype 6 lc rgb \"#edc948\"\n"
            "set linetype 7 lc rgb \"#b07aa1\"\nset linetype 8 lc rgb \"#9c755f\"\nset linetype 9 lc rgb \"#bab0ac\"\n";
  // The legend gives each stage's median: a stage far smaller than the largest is a sliver in the bars.
  script += "plot";
  for (std::size_t i = 0; i < stages.size(); ++i)
    script += fmt::format("{} \"{}.dat\" using {}{} title {}", i ? ", \\\n    " : "", stem, i + 2,
                          i ? "" : ":xtic(1)", legend[i]);
  script += "\n";
  if (Status s = write_file_atomically(folder / (stem + ".txt"), strings.data()); !s) return s.error();
  if (Status s = write_file_atomically(folder / (stem + ".dat"), data); !s) return s.error();
  if (Status s = write_file_atomically(folder / (stem + ".gp"), script); !s) return s.error();
  if (Status s = run_gnuplot(folder, stem + ".gp"); !s) return s.error();
  return image;
}

}  // namespace shatter
