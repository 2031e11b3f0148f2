#include "harness/cli/command.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_targets.h"
#include "harness/results/grid_merge.h"
#include "harness/results/grid_reader.h"
#include "harness/results/grid_reporter.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace shatter::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> parts;
  std::string out;
  bool repetitions = false;
};

int run_merge(const MergeOptions& o) {
  std::filesystem::path csv = o.out;
  csv.replace_extension(".csv");
  const std::vector<std::filesystem::path> inputs(o.parts.begin(), o.parts.end());
  if (Status s = check_outputs({{"--out", o.out}, {"--out (its CSV twin)", csv}}, baseline_folders(), inputs); !s)
    return fail_input(s.error().message);
  std::vector<StoredGrid> parts;
  for (const std::string& p : o.parts) {
    Result<StoredGrid> g = read_grid_results(p);
    if (!g) return fail_input(g.error().message);
    parts.push_back(std::move(*g));
  }
  Result<StoredGrid> merged = merge_grids(parts, o.repetitions ? MergeParts::repetitions : MergeParts::shards);
  if (!merged) return fail_input(merged.error().message);
  const GridReport report{merged->grid, merged->case_name, merged->case_block, merged->context, merged->input_block};
  const std::string json = make_grid_reporter("json")->render(report);
  const std::string table = make_grid_reporter("csv")->render(report);
  const FileContent set[] = {{o.out, json}, {csv, table}};
  if (Status s = write_files_atomically(set); !s) return fail_input("--out: " + s.error().message);
  std::cout << make_grid_reporter("markdown")->render(report) << std::flush;
  return merged->grid.passed() || merged->metric == "instructions" ? exit_ok : exit_gate_failed;
}

}  // namespace

void add_merge_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<MergeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join the shards of one grid (grid --shard K/N), or repeated runs of it, into one results file");
  cmd->add_option("PARTS", o->parts, "Results JSON files")->required();
  cmd->add_flag("--repetitions", o->repetitions,
                "The parts are runs of the same cells (e.g. interleaved with another build's): join their samples");
  cmd->add_option("--out", o->out, "The merged results JSON (and the CSV beside it)")->required();
  cmd->callback([o, &exit_code] { exit_code = run_merge(*o); });
}

}  // namespace shatter::cli
