#include "harness/results/figure_record.h"

#include "harness/results/sample_statistics.h"

#include <fmt/core.h>

#include <algorithm>
#include <cassert>

namespace shatter {

void FigureRecord::add(const FigureSpec& spec, double value) {
  for (Figure& f : figures_)
    if (f.spec.name == spec.name) {
      f = Figure{spec, value};
      return;
    }
  figures_.push_back(Figure{spec, value});
}

void FigureRecord::set(std::string_view name, double value) {
  for (Figure& f : figures_)
    if (f.spec.name == name) {
      f.value = value;
      return;
    }
  assert(false && "FigureRecord::set: no figure of that name");
}

const Figure* FigureRecord::find(std::string_view name) const {
  for (const Figure& f : figures_)
    if (f.spec.name == name) return &f;
  return nullptr;
}

double FigureRecord::value(std::string_view name) const {
  const Figure* f = find(name);
  assert(f != nullptr && "FigureRecord::value: no figure of that name");
  return f != nullptr ? f->value : 0.0;
}

double FigureRecord::value_or(std::string_view name, double fallback) const {
  const Figure* f = find(name);
  return f != nullptr ? f->value : fallback;
}

FigureRecord summarise_figures(const std::vector<const FigureRecord*>& samples) {
  FigureRecord out;
  if (samples.empty()) return out;
  std::vector<const Figure*> summarised;
  for (const Figure& f : samples.front()->figures())
    if (f.spec.summary != CellSummary::none) summarised.push_back(&f);
  std::stable_sort(summarised.begin(), summarised.end(),
                   [](const Figure* a, const Figure* b) { return a->spec.cell_order < b->spec.cell_order; });
  std::vector<double> values;
  for (const Figure* f : summarised) {
    values.clear();
    for (const FigureRecord* s : samples) values.push_back(s->value_or(f->spec.name, f->spec.fallback));
    FigureSpec spec = f->spec;
    double v = 0.0;
    switch (spec.summary) {
      case CellSummary::median:
        v = median_of(values);
        spec.kind = FigureKind::number;
        break;
      case CellSummary::max: v = *std::max_element(values.begin(), values.end()); break;
      case CellSummary::min: v = *std::min_element(values.begin(), values.end()); break;
      case CellSummary::all:
        v = std::all_of(values.begin(), values.end(), [](double x) { return x != 0.0; }) ? 1.0 : 0.0;
        break;
      case CellSummary::none: break;
    }
    out.add(spec, v);
  }
  return out;
}

std::string figure_text(const Figure& figure) {
  switch (figure.spec.kind) {
    case FigureKind::flag: return figure.value != 0.0 ? "true" : "false";
    case FigureKind::integer: return fmt::format("{:g}", figure.value);
    case FigureKind::number:
      return figure.spec.unit == "ms" ? fmt::format("{:.6f}", figure.value) : fmt::format("{:g}", figure.value);
  }
  return "";
}

}  // namespace shatter
