#include "harness/accuracy/fracture_accuracy.h"

#include "algorithms/core/self_intersection_verdicts.h"
#include "harness/accuracy/fracture_replay.h"
#include "harness/metrics/attribute_metrics.h"
#include "harness/metrics/fracture_acceptance.h"
#include "harness/metrics/fracture_metrics.h"
#include "harness/plugins/capable_fracturer.h"
#include "harness/results/attribute_metrics_json.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

namespace shatter {
namespace {

/// One fracturer at one knob setting.
struct Setting {
  std::unique_ptr<Fracturer> fracturer;
  int fragments = 0;
  std::optional<std::pair<std::string, double>> knob;  // the accuracy knob's key and value, when it has one
};

/// The exact reference that replays the plans, or why there is none.
using Replayer = Result<std::unique_ptr<Fracturer>>;

AccuracyPoint measure(const std::string& case_name, const Solid& solid, const std::optional<Impact>& impact,
                      const Setting& s, const FractureAccuracyOptions& options, SelfIntersectionVerdicts& verdicts,
                      const Replayer& replayer) {
  AccuracyPoint p;
  p.family = "fracture";
  p.case_name = case_name;
  p.algorithm = std::string(s.fracturer->name());
  p.knobs = {{"fragments", s.fragments}};
  p.knob = fmt::format("fragments={}", s.fragments);
  if (s.knob) {
    const double v = s.knob->second;
    if (v == std::floor(v) && std::abs(v) < 1e15) {  // whole numbers as integers, as a resolution is
      p.knobs[s.knob->first] = static_cast<long long>(v);
      p.knob += fmt::format(" {}={}", s.knob->first, static_cast<long long>(v));
    } else {
      p.knobs[s.knob->first] = v;
      p.knob += fmt::format(" {}={}", s.knob->first, v);
    }
  }
  FractureParams params;
  params.fragments = s.fragments;
  params.seed = 1;
  params.impact = impact;
  params.verdicts = &verdicts;

  std::vector<Fragment> fragments;
  for (int rep = 0; rep < options.repetitions; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<std::vector<Fragment>> out = s.fracturer->fracture(solid.mesh, params);
    const auto t1 = std::chrono::steady_clock::now();
    if (!out) {
      p.time_ms = std::numeric_limits<double>::quiet_NaN();
      p.figures = {{"failed", out.error().message}};
      return p;
    }
    p.samples_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    if (rep == 0) fragments = std::move(*out);
  }
  p.time_ms = median_of(p.samples_ms);

  FractureMetricsOptions metrics_options;
  metrics_options.partition_samples = options.partition_samples;
  const FractureMetrics m = fracture_metrics(solid.mesh, solid.mass, fragments, s.fragments, metrics_options);
  p.figures = {{"fragments", m.fragment_count},
               {"volume_error", m.volume_error},
               {"partition_error", m.partition_error},
               {"partition_samples", m.partition_samples},
               {"area_error", m.area_error},
               {"all_closed", m.all_closed},
               {"min_fragment_volume", m.min_fragment_volume}};
  const AttributeMetrics a = attribute_metrics(solid.mesh, fragments);
  if (a.measured) p.figures["attributes"] = attribute_metrics_json(a);
  // An invalid fracture has no accuracy: its failed checks are reported and it stays off the front.
  std::vector<std::string> failed = failed_fracture_checks(m, acceptance_for(*s.fracturer));
  for (std::string& check : failed_attribute_checks(a)) failed.push_back(std::move(check));
  if (!failed.empty()) {
    p.figures["failed_checks"] = failed;
    return p;
  }
  if (!replayer) {
    p.figures["failed"] = "exact replay: " + replayer.error().message;
    return p;
  }
  Result<std::vector<Fragment>> exact = exact_replay(*s.fracturer, *(*replayer)->cut_plan_replay(), solid.mesh, params);
  if (!exact) {
    p.figures["failed"] = "exact replay: " + exact.error().message;
    return p;
  }
  const ReplayMismatch r = replay_mismatch(fragments, *exact);
  p.figures["replay_fragments"] = r.exact_count;
  p.figures["replay_volume_error"] = r.max_relative_volume;
  p.figures["replay_unpaired_volume"] = r.unpaired_volume;
  p.error = std::max(r.max_relative_volume, r.unpaired_volume);
  return p;
}

/// The point of a fracturer that could not be made (a plugin's factory failed): failed, no figures.
AccuracyPoint uncreated(const std::string& case_name, const std::string& name, int fragments, const Error& why) {
  AccuracyPoint p;
  p.family = "fracture";
  p.case_name = case_name;
  p.algorithm = name;
  p.knobs = {{"fragments", fragments}};
  p.knob = fmt::format("fragments={}", fragments);
  p.time_ms = std::numeric_limits<double>::quiet_NaN();
  p.figures = {{"failed", why.message}};
  return p;
}

}  // namespace

std::vector<std::string> default_accuracy_fracturers(const Registries& registries) {
  std::vector<std::string> out;
  for (const std::string& name : registries.fracturers.names()) {
    Result<std::unique_ptr<Fracturer>> f = registries.fracturers.create(name);
    if (!f || !(*f)->exact_reference()) out.push_back(name);
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<double>>> accuracy_knobs(
    const Registries& registries, const std::string& name,
    const std::map<std::string, std::vector<double>, std::less<>>& sweeps) {
  std::vector<std::pair<std::string, std::vector<double>>> knobs;
  for (const SettingDoc& d : registries.fracturers.settings(name)) {
    if (d.accuracy_sweep.empty()) continue;
    const auto it = sweeps.find(d.key);
    knobs.emplace_back(d.key, it != sweeps.end() ? it->second : d.accuracy_sweep);
  }
  return knobs;
}

Result<std::vector<AccuracyPoint>> fracture_accuracy(const std::string& case_name, const Solid& solid,
                                                     const std::optional<Impact>& impact,
                                                     const FractureAccuracyOptions& options,
                                                     const Registries& registries) {
  const std::vector<std::string> names =
      options.fracturers.empty() ? default_accuracy_fracturers(registries) : options.fracturers;
  std::vector<AccuracyPoint> points;
  SelfIntersectionVerdicts verdicts;  // the solid is checked once for every setting and repetition
  const Replayer replayer = plan_replayer(registries.fracturers);
  for (const std::string& name : names) {
    const auto knobs = accuracy_knobs(registries, name, options.sweeps);
    for (const int n : options.fragments) {
      for (const auto& [key, values] : knobs)
        for (const double value : values) {
          Result<std::unique_ptr<Fracturer>> f = registries.fracturers.create(name, {{key, value}});
          if (!f) {
            points.push_back(uncreated(case_name, name, n, f.error()));
            continue;
          }
          Setting s{std::move(*f), n, std::make_pair(key, value)};
          points.push_back(measure(case_name, solid, impact, s, options, verdicts, replayer));
        }
      if (!knobs.empty()) continue;
      Result<std::unique_ptr<Fracturer>> f = registries.fracturers.create(name);
      if (!f) {
        points.push_back(uncreated(case_name, name, n, f.error()));
        continue;
      }
      Setting s{std::move(*f), n, std::nullopt};
      points.push_back(measure(case_name, solid, impact, s, options, verdicts, replayer));
    }
  }
  return points;
}

}  // namespace shatter
