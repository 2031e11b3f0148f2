#include "harness/pipeline/stage.h"

#include <algorithm>
#include <ctime>

namespace shatter {

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

void StageLog::ran(Stage stage) { ran_[static_cast<std::size_t>(stage)] = true; }

void StageLog::skipped(Stage stage, std::string reason) {
  StageSkip skip{std::string(stage_name(stage)), std::move(reason)};
  const bool known = std::any_of(skips_.begin(), skips_.end(), [&](const StageSkip& s) {
    return s.stage == skip.stage && s.reason == skip.reason;
  });
  if (!known) skips_.push_back(std::move(skip));
}

std::vector<std::string> StageLog::run() const {
  std::vector<std::string> out;
  for (const Stage s : kAllStages)
    if (ran_[static_cast<std::size_t>(s)]) out.emplace_back(stage_name(s));
  return out;
}

}  // namespace shatter
