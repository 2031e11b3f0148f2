#include "algorithms/stress/stress_model_registry.h"

#include <cassert>

namespace shatter {

void StressModelRegistry::add(std::string name, std::string description, StressModelFactory factory) {
  assert(description.find('\n') == std::string::npos);
  for ([[maybe_unused]] const Entry& e : entries_) assert(e.name != name && "stress model registered twice");
  entries_.push_back({std::move(name), std::move(description), std::move(factory)});
}

Result<std::unique_ptr<StressModel>> StressModelRegistry::create(std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.name == name) return e.factory();
  std::string known;
  for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.name;
  return Error{"unknown stress model '" + std::string(name) + "' (known: " + known + ")"};
}

std::vector<std::string> StressModelRegistry::names() const {
  std::vector<std::string> out;
  for (const Entry& e : entries_) out.push_back(e.name);
  return out;
}

std::string StressModelRegistry::description(std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.name == name) return e.description;
  return {};
}

}  // namespace shatter
