#include "harness/plugins/capable_fracturer.h"

#include <string>
#include <utility>

namespace shatter {
namespace {

/// The first registered fracturer (default settings) for which `capable` holds, or null.
template <class Capable>
std::unique_ptr<Fracturer> first_capable(const FracturerRegistry& fracturers, Capable&& capable) {
  for (const std::string& name : fracturers.names()) {
    Result<std::unique_ptr<Fracturer>> f = fracturers.create(name);
    if (f && capable(**f)) return std::move(*f);
  }
  return nullptr;
}

}  // namespace

Result<std::unique_ptr<Fracturer>> plane_cutter(const FracturerRegistry& fracturers, std::string_view preferred,
                                                const PluginSettings& settings) {
  if (!preferred.empty() && fracturers.contains(preferred)) {
    Result<std::unique_ptr<Fracturer>> own = fracturers.create(preferred, settings);
    if (own && (*own)->plane_cutting() != nullptr) return std::move(*own);
  }
  std::unique_ptr<Fracturer> f = first_capable(fracturers, [](const Fracturer& x) { return x.plane_cutting() != nullptr; });
  if (f == nullptr) return Error{"no registered fracturer cuts by given planes (Fracturer::plane_cutting)"};
  return f;
}

Result<std::unique_ptr<Fracturer>> plan_replayer(const FracturerRegistry& fracturers) {
  std::unique_ptr<Fracturer> f = first_capable(fracturers, [](const Fracturer& x) {
    return x.exact_reference() && x.cut_plan_replay() != nullptr;
  });
  if (f == nullptr) return Error{"no registered exact reference replays cut plans (Fracturer::cut_plan_replay)"};
  return f;
}

}  // namespace shatter
