#include "harness/accuracy/accuracy_point.h"

#include "harness/accuracy/pareto_front.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

namespace shatter {

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

void mark_pareto_front(std::vector<AccuracyPoint>& points) {
  std::map<std::pair<std::string, std::string>, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < points.size(); ++i) groups[{points[i].family, points[i].case_name}].push_back(i);
  for (const auto& [group, members] : groups) {
    std::vector<TimeError> te;
    for (const std::size_t i : members)
      te.push_back({points[i].time_ms, points[i].error.value_or(std::numeric_limits<double>::quiet_NaN())});
    const std::vector<bool> front = pareto_front(te);
    for (std::size_t k = 0; k < members.size(); ++k) points[members[k]].pareto = front[k];
  }
}

}  // namespace shatter
