#include "algorithms/registry/registries.h"
#include "harness/cli/command.h"
#include "harness/cli/progress_line.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_targets.h"
#include "harness/results/run_context.h"
#include "harness/stability/stability_battery.h"
#include "harness/stability/stability_table.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace shatter::cli {
namespace {

struct StabilityCommandOptions {
  std::string algorithm = "all";
  std::string model = "all";
  std::string json;
  bool quick = false;
  double timeout_s = 60.0;
  std::vector<std::string> hazards;
};

/// "all" -> every registered name; "none" -> nothing; a name -> itself when registered.
Result<std::vector<std::string>> pick(const std::string& wanted, const std::vector<std::string>& known,
                                      const std::string& flag) {
  if (wanted == "all") return known;
  if (wanted == "none") return std::vector<std::string>{};
  if (std::find(known.begin(), known.end(), wanted) != known.end()) return std::vector<std::string>{wanted};
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
  return Error{flag + ": unknown name '" + wanted + "' (known: all, none, " + list + ")"};
}

int run_stability_command(const StabilityCommandOptions& o, const Registries& registries) {
  Result<std::vector<std::string>> fracturers = pick(o.algorithm, registries.fracturers.names(), "--algo");
  if (!fracturers) return fail_input(fracturers.error().message);
  Result<std::vector<std::string>> models = pick(o.model, registries.stress_models.names(), "--model");
  if (!models) return fail_input(models.error().message);
  const std::vector<std::string> known = hazard_names();
  for (const std::string& h : o.hazards) {
    // The quick chain is named after its length; accept both spellings.
    if (std::find(known.begin(), known.end(), h) == known.end() && h != "chain-1000") {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      return fail_input("--hazard: unknown hazard '" + h + "' (known: " + list + ")");
    }
  }
  if (Status s = check_outputs({{"--json", o.json}}); !s) return fail_input(s.error().message);
  StabilityOptions options;
  options.fracturers = *fracturers;
  options.models = *models;
  options.quick = o.quick;
  options.time_limit_s = o.timeout_s;
  options.hazards = o.hazards;
  // On a terminal one line rewritten per result; elsewhere (a log, CI) one line per result.
  ProgressLine progress("stability", 0);
  const std::vector<HazardResult> results = run_stability(options, registries, [&progress](const HazardResult& r) {
    const std::string what = r.hazard + " / " + r.algorithm + ": " + std::string(outcome_tag(r.outcome));
    if (progress.shown())
      progress.step(what);
    else
      std::cerr << "stability: " << what << '\n';
  });
  progress.end();
  std::cout << stability_table(results);
  if (!o.json.empty()) {
    nlohmann::ordered_json doc = {{"context", to_json(current_context())}};
    const nlohmann::ordered_json body = stability_json(results, o.quick, o.timeout_s);
    for (const auto& [key, value] : body.items()) doc[key] = value;
    if (Status s = write_file_atomically(o.json, doc.dump(2) + "\n"); !s) return fail_input("--json: " + s.error().message);
  }
  return all_valid_or_rejected(results) ? exit_ok : exit_gate_failed;
}

}  // namespace

void add_stability_command(CLI::App& app, int& exit_code, const Registries& registries) {
  auto options = std::make_shared<StabilityCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stability", "Run the hazard battery on fracturers and stress models; exit 1 on CRASH, TIMEOUT or INVALID_OUTPUT");
  cmd->add_option("--algo", options->algorithm, "Fracturer name, all or none")->capture_default_str();
  cmd->add_option("--model", options->model, "Stress model name, all or none")->capture_default_str();
  cmd->add_option("--json", options->json, "Write the results as JSON here (atomically)");
  cmd->add_flag("--quick", options->quick, "Smaller deep-recursion and chain cases (100 fragments, 1,000 blocks)");
  cmd->add_option("--timeout", options->timeout_s, "Time limit per case and algorithm, s")
      ->check(CLI::Range(0.1, 86400.0))
      ->capture_default_str();
  cmd->add_option("--hazard", options->hazards, "Only these hazard cases (repeatable; default all)");
  cmd->callback([options, &exit_code, &registries] { exit_code = run_stability_command(*options, registries); });
}

}  // namespace shatter::cli
