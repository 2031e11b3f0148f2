#include "harness/accuracy/pareto_front.h"

#include <cmath>

namespace shatter {

std::vector<bool> pareto_front(std::span<const TimeError> points) {
  const auto finite = [](const TimeError& p) { return std::isfinite(p.time) && std::isfinite(p.error); };
  std::vector<bool> front(points.size(), false);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const TimeError& p = points[i];
    if (!finite(p)) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      const TimeError& q = points[j];
      if (j == i || !finite(q)) continue;
      dominated = q.time <= p.time && q.error <= p.error && (q.time < p.time || q.error < p.error);
    }
    front[i] = !dominated;
  }
  return front;
}

}  // namespace shatter
