#include "harness/results/worst_frame.h"

#include <algorithm>
#include <numeric>

namespace shatter {

int slowest_frame(const std::vector<double>& frame_ms) {
  if (frame_ms.empty()) return -1;
  return static_cast<int>(std::max_element(frame_ms.begin(), frame_ms.end()) - frame_ms.begin());
}

std::optional<WorstFrame> sample_worst_frame(const GridSample& sample, int repetition) {
  const int frame = slowest_frame(sample.frame_ms);
  if (frame < 0 || !sample.frame_stages_ms) return std::nullopt;
  WorstFrame w;
  w.repetition = repetition;
  w.frame = frame;
  w.ms = sample.frame_ms[static_cast<std::size_t>(frame)];
  w.stages = stage_times_in_frame(*sample.frame_stages_ms, static_cast<std::size_t>(frame));
  return w;
}

std::optional<WorstFrame> cell_worst_frame(const GridCell& cell) {
  if (cell.samples.empty()) return std::nullopt;
  std::vector<int> order(cell.samples.size());
  std::iota(order.begin(), order.end(), 0);
  const auto worst = [&](int k) { return cell.samples[static_cast<std::size_t>(k)].worst_frame_ms; };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return worst(a) < worst(b); });
  const int median = order[(order.size() - 1) / 2];
  return sample_worst_frame(cell.samples[static_cast<std::size_t>(median)], median);
}

std::vector<std::pair<Stage, double>> largest_stages(const StageTimes& stages, std::size_t count) {
  std::vector<std::pair<Stage, double>> out;
  for (const Stage s : kAllStages)
    if (stages[static_cast<std::size_t>(s)] > 0.0) out.emplace_back(s, stages[static_cast<std::size_t>(s)]);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  if (out.size() > count) out.resize(count);
  return out;
}

}  // namespace shatter
