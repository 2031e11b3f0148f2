#include "algorithms/core/self_intersection_verdicts.h"
#include "algorithms/fracture/fracture_limits.h"
#include "harness/limits.h"
#include "algorithms/registry/registries.h"
#include "harness/cases/load_solid.h"
#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_folder.h"
#include "harness/results/fragment_writer.h"
#include "harness/output/output_targets.h"
#include "harness/results/run_context.h"
#include "harness/metrics/fracture_acceptance.h"
#include "harness/metrics/fracture_metrics.h"
#include "harness/results/markdown_text.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace shatter::cli {
namespace {

struct TableOptions {
  std::vector<std::string> meshes;
  std::vector<std::string> algorithms;
  std::vector<int> fragments = {5, 25, 100};
  int repetitions = 3;
  bool no_repair = false;
  double cap_uv_scale = 0.0;  // 0: the default
  std::string json;           // --json: the table results JSON (docs/results.md)
  std::string out;            // --out: every row's fragments of seed 1, one fragments folder each
  RecordFlags record;         // --record, --db
};

/// One row's fragments of seed 1, for `--out`.
struct FragmentsFolder {
  std::string sub;                  // DIR/<mesh index>-<mesh file>/<requested>/<fracturer>
  std::string mesh;                 // the mesh file as given
  std::vector<Fragment> fragments;  // of seed 1
  double time_ms = 0.0;             // the row's median
  FractureMetrics metrics;          // of seed 1
  std::string algorithm;
  int requested = 0;
};

/// The fragments folder summary of one row (docs/results.md, "Fragments folder").
std::string folder_summary(const FragmentsFolder& f) {
  const nlohmann::ordered_json j = {
      {"kind", "fracture"},
      {"schema_version", 1},
      {"algorithm", f.algorithm},
      {"fragments", f.fragments.size()},
      {"requested", f.requested},
      {"seed", 1},
      {"time_ms", f.time_ms},
      {"input", {{"file", f.mesh}}},
      {"metrics",
       {{"volume_error", f.metrics.volume_error},
        {"all_closed", f.metrics.all_closed},
        {"partition_error", f.metrics.partition_error},
        {"area_error", f.metrics.area_error},
        {"min_fragment_volume", f.metrics.min_fragment_volume}}},
  };
  return j.dump(1) + "\n";
}

/// Writes `dir` holding one fragments folder per row, whole or not at all.
Status write_fragments_folders(const std::filesystem::path& dir, const std::vector<FragmentsFolder>& folders) {
  return write_folder_atomically(dir, [&](const std::filesystem::path& staging) -> Status {
    for (const FragmentsFolder& f : folders) {
      const std::filesystem::path target = staging / f.sub;
      std::error_code ec;
      std::filesystem::create_directories(target, ec);
      if (ec) return Error{target.string() + ": cannot create: " + ec.message()};
      if (Status s = write_fragment_files(target, f.fragments, std::filesystem::path(f.mesh).parent_path(), folder_summary(f)); !s)
        return s;
    }
    return {};
  });
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

int run_table(TableOptions o, const Registries& r) {
  const std::vector<std::filesystem::path> inputs(o.meshes.begin(), o.meshes.end());
  if (Status s = check_outputs({{"--json", o.json}, {"--out", o.out, true}}, baseline_folders(), inputs); !s)
    return fail_input(s.error().message);
  if (Status s = check_record_target(o.record); !s) return fail_input(s.error().message);
  if (o.algorithms.empty()) o.algorithms = r.fracturers.names();
  // A fracturer whose code failed to make it (a plugin's factory threw or gave a null) is a failed row
  // of its own; an unknown name or bad settings are the command line's error.
  struct Candidate {
    std::string name;
    std::unique_ptr<Fracturer> fracturer;  // null when it could not be made
    Error error;
  };
  std::vector<Candidate> fracturers;
  for (const std::string& name : o.algorithms) {
    auto f = r.fracturers.create(name);
    if (!f && f.error().cause != ErrorCause::algorithm_fault) return fail_input("--algo: " + f.error().message);
    fracturers.push_back(f ? Candidate{name, std::move(*f), {}} : Candidate{name, nullptr, f.error()});
  }
  std::vector<Solid> solids;
  for (const std::string& path : o.meshes) {
    Result<Solid> s = load_solid(path, o.no_repair ? SolidRepair::refuse : SolidRepair::repair,
                                 CutFaceOptions{.uv_scale = o.cap_uv_scale, .interior = {}});
    if (!s) return fail_input(s.error().message);
    solids.push_back(std::move(*s));
  }

  std::vector<FragmentsFolder> folders;  // --out: written together at the end
  std::vector<std::string> failed;  // checks failed by rows, named by mesh, fracturer and count
  nlohmann::ordered_json json_rows = nlohmann::ordered_json::array();
  SelfIntersectionVerdicts verdicts;  // each mesh's input check runs once for every row and repetition
  fmt::print("| mesh | triangles | fracturer | requested | fragments | median ms | x fastest | volume error "
             "| partition error | area error | closed | min volume |\n");
  fmt::print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|---:|\n");
  for (std::size_t m = 0; m < solids.size(); ++m) {
    const Solid& solid = solids[m];
    const std::string mesh_name = std::filesystem::path(o.meshes[m]).filename().string();
    for (int n : o.fragments) {
      struct Row {
        std::string algorithm;
        std::string refused;  // a fracturer's refusal of this input (e.g. self-intersecting): shown, not fatal
        bool fault = false;   // the refusal is a fault of its code (ErrorCause::algorithm_fault): the run fails
        double ms;
        std::vector<double> samples_ms;
        std::size_t count;
        FractureMetrics metrics;
        FractureAcceptance acceptance;  // the fracturer's (acceptance_for)
      };
      std::vector<Row> rows;
      for (const Candidate& candidate : fracturers) {
        if (!candidate.fracturer) {
          rows.push_back({candidate.name, candidate.error.message, true, 0.0, {}, 0, {}, {}});
          continue;
        }
        const Fracturer* fracturer = candidate.fracturer.get();
        std::vector<double> times;
        std::vector<Fragment> first;
        std::string refused;
        bool fault = false;
        for (int rep = 0; rep < o.repetitions && refused.empty(); ++rep) {
          FractureParams params;
          params.fragments = n;
          params.seed = static_cast<std::uint64_t>(rep + 1);
          params.verdicts = &verdicts;
          const auto t0 = std::chrono::steady_clock::now();
          auto fragments = fracturer->fracture(solid.mesh, params);
          const auto t1 = std::chrono::steady_clock::now();
          if (!fragments) {
            refused = fragments.error().message;
            fault = fragments.error().cause == ErrorCause::algorithm_fault;
            break;
          }
          times.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
          if (rep == 0) first = std::move(*fragments);
        }
        if (!refused.empty()) {
          rows.push_back({candidate.name, refused, fault, 0.0, {}, 0, {}, {}});
          continue;
        }
        rows.push_back({candidate.name, {}, false, median(times), times, first.size(),
                        fracture_metrics(solid.mesh, solid.mass, first, n), acceptance_for(*fracturer)});
        if (!o.out.empty())
          folders.push_back({fmt::format("{}-{}/{}/{}", m, safe_file_name(mesh_name), n, safe_file_name(candidate.name)),
                             o.meshes[m], std::move(first), rows.back().ms, rows.back().metrics, candidate.name, n});
      }
      double fastest = std::numeric_limits<double>::infinity();
      for (const Row& row : rows)
        if (row.refused.empty()) fastest = std::min(fastest, row.ms);
      for (const Row& row : rows)
        if (row.refused.empty())
          for (const std::string& check : failed_fracture_checks(row.metrics, row.acceptance))
            failed.push_back(fmt::format("{} {} {} fragments: {}", mesh_name, row.algorithm, n, check));
      for (const Row& row : rows) {
        nlohmann::ordered_json j = {{"mesh", mesh_name}, {"triangles", solid.mesh.triangle_count()},
                                    {"algorithm", row.algorithm}, {"fragments", n}};
        if (!row.refused.empty()) {
          j[row.fault ? "failed" : "refused"] = row.refused;
        } else {
          j["produced"] = row.count;
          j["time_ms"] = row.ms;
          j["samples_ms"] = row.samples_ms;
          j["figures"] = {{"volume_error", row.metrics.volume_error},
                          {"partition_error", row.metrics.partition_error},
                          {"area_error", row.metrics.area_error},
                          {"all_closed", row.metrics.all_closed},
                          {"min_fragment_volume", row.metrics.min_fragment_volume}};
        }
        json_rows.push_back(std::move(j));
      }
      for (const Row& row : rows)
        if (row.fault) failed.push_back(fmt::format("{} {} {} fragments: {}", mesh_name, row.algorithm, n, row.refused));
      for (const Row& row : rows)
        if (!row.refused.empty())
          fmt::print("| {} | {} | {} | {} | {}: {} | | | | | | | |\n", mesh_name, solid.mesh.triangle_count(),
                     row.algorithm, n, row.fault ? "failed" : "refused", markdown_cell(row.refused));
        else
          fmt::print("| {} | {} | {} | {} | {} | {:.3f} | {:.1f} | {:.2e} | {:.4f} | {:.2e} | {} | {:.3e} |\n",
                   mesh_name, solid.mesh.triangle_count(), row.algorithm, n, row.count, row.ms,
                   fastest > 0 && std::isfinite(fastest) ? row.ms / fastest : 1.0, row.metrics.volume_error, row.metrics.partition_error,
                   row.metrics.area_error, row.metrics.all_closed ? "yes" : "NO", row.metrics.min_fragment_volume);
    }
  }
  fmt::print("\nmedian of {} repetitions (seeds 1..{}); error figures of seed 1; x fastest = median / fastest "
             "median in the same row group\n",
             o.repetitions, o.repetitions);
  if (!o.json.empty() || o.record.record) {
    nlohmann::ordered_json j;
    j["schema_version"] = 1;
    j["kind"] = "table";
    j["context"] = to_json(current_context());
    j["repetitions"] = o.repetitions;
    j["meshes"] = o.meshes;
    j["passed"] = failed.empty();
    j["rows"] = std::move(json_rows);
    const std::string text = j.dump(1) + "\n";
    if (!o.json.empty())
      if (Status s = write_file_atomically(o.json, text); !s) return fail_input("--json: " + s.error().message);
    if (const int code = record_if_asked(o.record, text, o.json.empty() ? "table.json" : o.json); code != exit_ok)
      return code;
  }
  if (!o.out.empty())
    if (Status s = write_fragments_folders(o.out, folders); !s) return fail_input("--out: " + s.error().message);
  // The table is printed whole; a row whose figures fail the checks makes the run fail.
  return print_failed_checks("", failed) > 0 ? exit_gate_failed : exit_ok;
}

}  // namespace

void add_table_command(CLI::App& app, int& exit_code, const Registries& registries) {
  auto options = std::make_shared<TableOptions>();
  CLI::App* cmd = app.add_subcommand(
      "table", "Fracture meshes with every fracturer and print a Markdown table of time and error figures");
  cmd->add_option("--mesh", options->meshes, "Input meshes (.off, .obj, .glb, .gltf, .fbx, .ply, .stl, ...; docs/cli.md, Formats); repaired into solids when they are not")
      ->required();
  cmd->add_flag("--no-repair", options->no_repair, "Refuse a mesh that is not a solid instead of repairing it");
  add_cap_uv_scale_option(cmd, options->cap_uv_scale);
  cmd->add_option("--algo", options->algorithms, "Fracturers (default: every registered one)");
  cmd->add_option("--fragments", options->fragments, "Requested fragment counts")
      ->check(CLI::Range(1, kMaxFragments))
      ->capture_default_str();
  cmd->add_option("--repetitions", options->repetitions, "Runs per cell, seeds 1..R; the median time is shown")
      ->check(CLI::Range(1, kMaxRepetitions))
      ->capture_default_str();
  cmd->add_option("--json", options->json, "Write the table results JSON here (docs/results.md)");
  cmd->add_option("--out", options->out,
                  "Folder for every row's fragments of seed 1, one fragments folder each (MESH/REQUESTED/FRACTURER; "
                  "for report's 3D views), replaced as a whole");
  add_record_flags(cmd, options->record);
  cmd->callback([options, &exit_code, &registries] { exit_code = run_table(*options, registries); });
}

}  // namespace shatter::cli
