#include "harness/stability/stability_battery.h"

#include "harness/stability/fracture_hazards.h"
#include "harness/process/isolated_run.h"
#include "harness/stability/stress_hazards.h"

#include <algorithm>

namespace shatter {
namespace {

bool selected(const StabilityOptions& o, const std::string& name) {
  return o.hazards.empty() || std::find(o.hazards.begin(), o.hazards.end(), name) != o.hazards.end();
}

/// Runs `work` (which returns a HazardResult as JSON text) isolated and turns its end into a result.
HazardResult isolated(const std::function<HazardResult()>& work, const std::string& hazard,
                      const std::string& algorithm, const std::string& kind, double time_limit_s) {
  const IsolatedRun run = run_isolated([&] { return to_json(work()).dump(); }, time_limit_s);
  HazardResult r;
  r.hazard = hazard;
  r.algorithm = algorithm;
  r.kind = kind;
  if (run.end == IsolatedRun::End::timed_out) {
    r.outcome = HazardOutcome::timeout;
    r.detail = "killed after " + std::to_string(static_cast<int>(time_limit_s)) + " s";
  } else if (run.end == IsolatedRun::End::crashed) {
    r.outcome = HazardOutcome::crash;
    r.detail = run.detail;
  } else {
    const nlohmann::json j = nlohmann::json::parse(run.output, nullptr, false);
    if (j.is_discarded() || !from_json(j, r)) {
      r.outcome = HazardOutcome::crash;
      r.detail = "the child ended without a verdict";
    }
  }
  r.time_ms = run.time_ms;
  return r;
}

}  // namespace

std::vector<HazardResult> run_stability(const StabilityOptions& o,
                                        const std::function<void(const HazardResult&)>& progress) {
  std::vector<HazardResult> out;
  const auto add = [&](HazardResult r) {
    if (progress) progress(r);
    out.push_back(std::move(r));
  };
  if (!o.fracturers.empty())
    for (const FractureHazard& h : fracture_hazards(o.quick)) {
      if (!selected(o, h.name)) continue;
      for (const std::string& algo : o.fracturers)
        add(isolated([&] { return run_fracture_hazard(h, algo); }, h.name, algo, "fracture", o.time_limit_s));
    }
  if (!o.models.empty())
    for (const StressHazard& h : stress_hazards(o.quick)) {
      if (!selected(o, h.name)) continue;
      for (const std::string& model : o.models)
        add(isolated([&] { return run_stress_hazard(h, model); }, h.name, model, "stress", o.time_limit_s));
    }
  return out;
}

std::vector<std::string> hazard_names() {
  std::vector<std::string> names;
  for (const FractureHazard& h : fracture_hazards(false)) names.push_back(h.name);
  for (const StressHazard& h : stress_hazards(false)) names.push_back(h.name);
  return names;
}

bool all_valid_or_rejected(const std::vector<HazardResult>& results) {
  return std::all_of(results.begin(), results.end(), [](const HazardResult& r) {
    return r.outcome == HazardOutcome::valid || r.outcome == HazardOutcome::rejected_input;
  });
}

}  // namespace shatter
