#include "harness/report/pareto_plot.h"

#include "harness/report/gnuplot_runner.h"
#include "harness/report/gnuplot_text.h"
#include "harness/output/atomic_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shatter {

Result<std::string> plot_pareto(const std::vector<AccuracyPoint>& points, const std::string& family,
                                const std::string& case_name, const std::filesystem::path& folder,
                                const std::string& stem) {
  std::vector<const AccuracyPoint*> shown;
  std::vector<std::string> algorithms;
  double smallest = std::numeric_limits<double>::infinity();
  for (const AccuracyPoint& p : points) {
    if (p.family != family || p.case_name != case_name || !p.error || !std::isfinite(p.time_ms)) continue;
    shown.push_back(&p);
    if (std::find(algorithms.begin(), algorithms.end(), p.algorithm) == algorithms.end()) algorithms.push_back(p.algorithm);
    if (*p.error > 0.0) smallest = std::min(smallest, *p.error);
  }
  if (shown.empty()) return Error{family + " on " + case_name + ": no point with a time and an error"};
  const double floor = std::isfinite(smallest) ? std::pow(10.0, std::floor(std::log10(smallest)) - 1.0) : 1e-16;
  bool floored = false;
  const auto y = [&](const AccuracyPoint& p) {
    floored = floored || *p.error <= 0.0;
    return *p.error > 0.0 ? *p.error : floor;
  };

  // Short point labels: "25", "25 r8", "32 cg 1e-06", "32 cg cap 10".
  const auto short_knob = [](std::string k) {
    const std::pair<const char*, const char*> replacements[] = {
        {"fragments=", ""}, {" resolution=", " r"}, {" max_cells=", " c"}, {"slabs=", ""}, {" solver=default", ""},
        {"solver=default", "default"}, {" solver=cg tol=1e-12 cap=", " cg cap "}, {" solver=cg tol=", " cg "},
        {" cap=20000", ""}};
    for (const auto& [from, to] : replacements)
      for (std::size_t at = k.find(from); at != std::string::npos; at = k.find(from, at + std::string(to).size()))
        k.replace(at, std::string(from).size(), to);
    return k;
  };
  // Labels that would print over one already placed (closer than about a label's size on the log
  // axes) are left out; front labels are placed first and always kept, alternately above and below.
  std::vector<std::pair<double, double>> placed;
  const auto crowded = [&](double t, double e) {
    for (const auto& [pt, pe] : placed)
      if (std::abs(std::log10(t / pt)) < 0.12 && std::abs(std::log10(e / pe)) < 0.25) return true;
    return false;
  };
  std::vector<const AccuracyPoint*> front;
  for (const AccuracyPoint* p : shown)
    if (p->pareto) front.push_back(p);
  std::sort(front.begin(), front.end(), [](const AccuracyPoint* a, const AccuracyPoint* b) { return a->time_ms < b->time_ms; });
  std::string front_data = "# Pareto front: time error label label_x label_y\n";
  for (std::size_t i = 0; i < front.size(); ++i) {
    const AccuracyPoint& p = *front[i];
    const double ly = i % 2 == 0 ? y(p) * 1.6 : y(p) / 1.9;
    front_data += fmt::format("{:.6g} {:.6g} {} {:.6g} {:.6g}\n", p.time_ms, y(p),
                              gnuplot_data_field(p.algorithm + " " + short_knob(p.knob)), p.time_ms * 1.06, ly);
    placed.emplace_back(p.time_ms, y(p));
  }

  // One data block per algorithm (index a), then the front sorted by time (last index).
  std::string data;
  for (std::size_t a_index = 0; a_index < algorithms.size(); ++a_index) {
    const std::string& a = algorithms[a_index];
    data += fmt::format("# algorithm {} (names in the .txt file beside this one)\n", a_index + 1);
    for (const AccuracyPoint* p : shown) {
      if (p->algorithm != a) continue;
      std::string label;
      if (!p->pareto && !crowded(p->time_ms, y(*p))) {
        label = short_knob(p->knob);
        placed.emplace_back(p->time_ms, y(*p));
      }
      data += fmt::format("{:.6g} {:.6g} {}\n", p->time_ms, y(*p), gnuplot_data_field(label));
    }
    data += "\n\n";
  }
  data += front_data;

  const std::string image = stem + ".png";
  // Names from the results file (case, algorithms) are data (gnuplot_text.h).
  GnuplotStrings strings;
  const std::string title = strings.add(
      fmt::format("{} on {}: time against error, Pareto front dashed and labelled in bold{}", family, case_name,
                  floored ? fmt::format(" (error 0 drawn at {:.0e})", floor) : std::string()));
  std::vector<std::string> legend;
  for (const std::string& a : algorithms) legend.push_back(strings.add(a));
  std::string script;
  script += "set terminal pngcairo noenhanced size 1000,640 font \"Sans,10\"\n";
  script += fmt::format("set output \"{}\"\n", image);
  script += strings.load(stem + ".txt");
  script += fmt::format("set title {} . \"\\npoint labels: knob (fragments, r = fem-lite resolution; slabs, cg = CG tolerance or iteration cap)\"\n", title);
  script += "set logscale xy\nset format y \"%.0e\"\nset grid\nset key outside right top\n";
  script += "set xlabel \"time (ms, median of the repetitions)\"\n";
  script += family == "fracture"    ? "set ylabel \"replay error (relative volume mismatch)\"\n"
            : family == "colliders" ? "set ylabel \"largest share of a piece's hull volume cut off\"\n"
            : family == "cascade"   ? "set ylabel \"share of bonds broken or fragments falling unlike the exact cascade\"\n"
                                    : "set ylabel \"error (relative, against the reference)\"\n";
  script += "set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1\n";
  script += "set linetype 1 lc rgb \"#4e79a7\" pt 7\nset linetype 2 lc rgb \"#e15759\" pt 5\n"
            "set linetype 3 lc rgb \"#59a14f\" pt 9\nset linetype 4 lc rgb \"#b07aa1\" pt 11\n"
            "set linetype 5 lc rgb \"#f28e2b\" pt 13\n";
  std::vector<std::string> plots;
  for (std::size_t a = 0; a < algorithms.size(); ++a)
    plots.push_back(fmt::format("\"{}.dat\" index {} using 1:2 with points lt {} ps 1.6 title {}", stem, a, a + 1, legend[a]));
  for (std::size_t a = 0; a < algorithms.size(); ++a)
    plots.push_back(fmt::format(
        "\"{}.dat\" index {} using 1:2:3 with labels left offset 0.7,-0.5 font \"Sans,7\" tc rgb \"#777777\" notitle", stem, a));
  // A file whose points mark no front draws none (gnuplot 5.4 crashes labelling a block of NaN).
  if (!front.empty()) {
    const std::size_t f = algorithms.size();
    plots.push_back(fmt::format("\"{}.dat\" index {} using 1:2 with steps lc rgb \"black\" dt 2 lw 1.5 title \"Pareto front\"", stem, f));
    plots.push_back(fmt::format("\"{}.dat\" index {} using 4:5:3 with labels left font \"Sans Bold,8\" notitle", stem, f));
  }
  script += "plot \\\n";
  for (std::size_t i = 0; i < plots.size(); ++i) script += "  " + plots[i] + (i + 1 < plots.size() ? ", \\\n" : "\n");
  if (Status s = write_file_atomically(folder / (stem + ".txt"), strings.data()); !s) return s.error();
  if (Status s = write_file_atomically(folder / (stem + ".dat"), data); !s) return s.error();
  if (Status s = write_file_atomically(folder / (stem + ".gp"), script); !s) return s.error();
  if (Status s = run_gnuplot(folder, stem + ".gp"); !s) return s.error();
  return image;
}

}  // namespace shatter
