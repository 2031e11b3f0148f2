#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/registry/registries.h"
#include "harness/cases/isolated_import.h"
#include "harness/cases/load_solid.h"
#include "harness/cli/command.h"
#include "harness/output/output_targets.h"
#include "harness/metrics/fracture_acceptance.h"
#include "harness/metrics/fracture_metrics.h"
#include "harness/results/attribute_metrics_json.h"
#include "harness/results/fragment_writer.h"
#include "harness/results/input_solid_json.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace shatter::cli {
namespace {

struct FractureOptions {
  std::string mesh;
  std::string algorithm = "plane-slice";
  int fragments = 10;
  std::uint64_t seed = 1;
  std::string out;
  std::vector<double> impact;  // x, y, z; empty: no impact
  double radius = 0.0;
  bool no_repair = false;
  double cap_uv_scale = 0.0;  // 0: the default
};

/// Wall time of each stage of the command, ms, in the order they run.
class StageClock {
 public:
  /// Ends the running stage as `name` and starts the next.
  void lap(const char* name) {
    const auto now = std::chrono::steady_clock::now();
    stages_[name] = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
  }
  /// The stages so far, {"read": ms, ...}.
  [[nodiscard]] const nlohmann::ordered_json& stages() const { return stages_; }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  nlohmann::ordered_json stages_ = nlohmann::ordered_json::object();
};

int run_fracture(const FractureOptions& o, const Registries& registries) {
  StageClock clock;
  if (Status s = check_outputs({{"--out", o.out, true}}, baseline_folders(), {o.mesh}); !s)
    return fail_input(s.error().message);
  Result<Mesh> read = read_asset_isolated(o.mesh);
  if (!read) return fail_input(read.error().message);
  clock.lap("read");
  Result<Solid> solid = make_solid(std::move(*read), o.mesh, o.no_repair ? SolidRepair::refuse : SolidRepair::repair,
                                   CutFaceOptions{.uv_scale = o.cap_uv_scale, .interior = {}});
  if (!solid) return fail_input(solid.error().message);
  clock.lap("solid");
  Result<std::unique_ptr<Fracturer>> fracturer = registries.fracturers.create(o.algorithm);
  if (!fracturer) return fail_algorithm("--algo", fracturer.error());

  FractureParams params;
  params.fragments = o.fragments;
  params.seed = o.seed;
  if (!o.impact.empty()) {
    Impact impact;
    impact.point = Vec3(o.impact[0], o.impact[1], o.impact[2]);
    impact.radius = o.radius;
    params.impact = impact;
  }
  clock.lap("setup");
  const auto start = std::chrono::steady_clock::now();
  Result<std::vector<Fragment>> fragments = (*fracturer)->fracture(solid->mesh, params);
  const auto stop = std::chrono::steady_clock::now();
  if (!fragments) return fail_algorithm(o.mesh, fragments.error());
  const double time_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  clock.lap("fracture");

  const FractureMetrics m = fracture_metrics(solid->mesh, solid->mass, *fragments, o.fragments);
  clock.lap("metrics");
  const AttributeMetrics a = attribute_metrics(solid->mesh, *fragments);
  clock.lap("attribute_metrics");
  nlohmann::ordered_json input = {{"file", o.mesh}};
  input.update(input_solid_json(*solid));
  nlohmann::ordered_json out = {
      {"algorithm", o.algorithm},
      {"fragments", fragments->size()},
      {"requested", o.fragments},
      {"seed", o.seed},
      {"time_ms", time_ms},
      {"input", input},
      {"metrics",
       {{"volume_error", m.volume_error},
        {"all_closed", m.all_closed},
        {"partition_error", m.partition_error},
        {"partition_samples", m.partition_samples},
        {"area_error", m.area_error},
        {"min_fragment_volume", m.min_fragment_volume},
        {"attributes", attribute_metrics_json(a)}}},
  };
  if (!o.out.empty()) {
    // The folder says what made it (report groups and labels folders by it).
    nlohmann::ordered_json summary = {{"kind", "fracture"}, {"schema_version", 1}};
    summary.update(out);
    if (Status s = write_fragments(o.out, *fragments, std::filesystem::path(o.mesh).parent_path(), summary.dump(1) + "\n"); !s)
      return fail_input(s.error().message);
  }
  clock.lap("write");
  // Printed only: the folder is written before its own time is known.
  out["stages_ms"] = clock.stages();
  std::cout << out.dump(2) << '\n';
  // The result is printed either way; a result its own figures call invalid is not a success.
  std::vector<std::string> failed = failed_fracture_checks(m, acceptance_for(**fracturer));
  for (std::string& check : failed_attribute_checks(a)) failed.push_back(std::move(check));
  return print_failed_checks(o.mesh, failed) > 0 ? exit_gate_failed : exit_ok;
}

}  // namespace

void add_fracture_command(CLI::App& app, int& exit_code, const Registries& registries) {
  auto options = std::make_shared<FractureOptions>();
  CLI::App* cmd = app.add_subcommand("fracture", "Fracture one mesh and print time and error figures as JSON");
  cmd->add_option("--mesh", options->mesh, "Input mesh (.off, .obj, .glb, .gltf, .fbx, .ply, .stl, ...; docs/cli.md, Formats); repaired into a solid when it is not one")
      ->required();
  cmd->add_flag("--no-repair", options->no_repair, "Refuse a mesh that is not a solid instead of repairing it");
  add_cap_uv_scale_option(cmd, options->cap_uv_scale);
  cmd->add_option("--algo", options->algorithm, "Fracturer name (see `shatterbench list`)")
      ->capture_default_str();
  cmd->add_option("--fragments", options->fragments, "Requested fragment count")
      ->check(CLI::Range(1, kMaxFragments))
      ->capture_default_str();
  cmd->add_option("--seed", options->seed, "Random seed (same seed, same fragments)")->capture_default_str();
  cmd->add_option("--out", options->out, "Folder for fragment_NNN.obj (nothing is written without it)");
  cmd->add_option("--impact", options->impact, "Impact point x,y,z (m): impact-aware fracturers refine around it")
      ->delimiter(',')
      ->expected(3);
  cmd->add_option("--radius", options->radius, "Impact radius (m), with --impact")
      ->check(CLI::Validator(
          [](const std::string& text) {
            double value = 0.0;
            return CLI::detail::lexical_cast(text, value) && value >= 0.0 && std::isfinite(value)
                       ? std::string()
                       : "must be a finite number >= 0, got " + text;
          },
          "NUMBER >= 0"))
      ->needs("--impact");
  cmd->callback([options, &exit_code, &registries] { exit_code = run_fracture(*options, registries); });
}

}  // namespace shatter::cli
