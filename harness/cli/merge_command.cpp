#include "harness/cli/command.h"
#include "harness/results/atomic_file.h"
#include "harness/results/grid_merge.h"
#include "harness/results/grid_reader.h"
#include "harness/results/grid_report.h"

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
  std::vector<StoredGrid> parts;
  for (const std::string& p : o.parts) {
    Result<StoredGrid> g = read_grid_results(p);
    if (!g) return fail_input(g.error().message);
    parts.push_back(std::move(*g));
  }
  Result<StoredGrid> merged = merge_grids(parts, o.repetitions ? MergeParts::repetitions : MergeParts::shards);
  if (!merged) return fail_input(merged.error().message);
  if (std::filesystem::is_directory(o.out)) return fail_input("--out: " + o.out + " is a folder, not a file");
  std::error_code ec;
  const auto parent = std::filesystem::path(o.out).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (ec) return fail_input("--out: cannot create folder " + parent.string() + ": " + ec.message());
  const std::string json = grid_to_json(merged->grid, merged->case_block, merged->context).dump(1) + "\n";
  if (Status s = write_file_atomically(o.out, json); !s) return fail_input("--out: " + s.error().message);
  std::filesystem::path csv = o.out;
  csv.replace_extension(".csv");
  if (Status s = write_file_atomically(csv, grid_to_csv(merged->grid)); !s) return fail_input("--out: " + s.error().message);
  std::cout << grid_to_markdown(merged->grid, merged->case_name) << std::flush;
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
