// Hostile inputs that used to give a wrong number with exit 0: a stress solve reported converged far
// from its tolerance, physical values outside what a double carries through the solve, compare on a
// zero base or a non-finite results file, one run merged twice, seeds and numeric flags that wrap,
// saturate or read NaN, and a damaged pre-fracture cache entry. Every input is generated here.

#include "tests/hostile/hostile_support.h"
#include "algorithms/registry/register_all.h"
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "harness/cases/case_loader.h"
#include "harness/cli/numeric_flags.h"
#include "harness/compare/grid_compare.h"
#include "harness/results/grid_merge.h"
#include "harness/results/grid_reader.h"
#include "harness/results/grid_report.h"
#include "fixtures/structures.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

using namespace shatter;
using shatter::test::line_count;
using shatter::test::run_cli;
using shatter::test::run_cli_argv;
namespace fs = std::filesystem;
using shatter::test::hostile_scratch;
using shatter::test::put_file;

namespace {

/// Exit 2 with exactly one stderr line that holds `needle`, and nothing on stdout.
void check_refused(const shatter::test::CliRun& r, const std::string& needle) {
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(line_count(r.err) == 1);
  CHECK(r.err.find("shatterbench: error:") == 0);
  CHECK(r.err.find(needle) != std::string::npos);
  CHECK(r.out.empty());
}

/// A cantilever of four slabs, anchored at x = 0, built by explicit cuts.
SupportGraph cantilever_graph(double density) {
  const std::vector<Fragment> slabs =
      fixtures::sliced_box(Vec3(2.0, 0.2, 0.3), Vec3(1.0, 0.0, 0.0), fixtures::planes_at(0, {0.5, 1.0, 1.5}));
  return fixtures::graph_of(slabs, {fixtures::box_region(Vec3(-1, -1, -1), Vec3(0.001, 1, 1))}, density);
}

/// A small valid case (a box cut in slabs, anchored at one end); `patch` is merged over it.
nlohmann::json small_case(const nlohmann::json& patch = nlohmann::json::object()) {
  nlohmann::json c = nlohmann::json::parse(R"({
    "mesh": {"box": {"size": [2, 0.2, 0.3], "center": [1, 0, 0]}},
    "material": {"density": 2000},
    "anchors": [{"box": {"min": [-1, -1, -1], "max": [0.001, 1, 1]}}],
    "prefracture": {"planes": [{"point": [0.5, 0, 0], "normal": [1, 0, 0]},
                               {"point": [1.0, 0, 0], "normal": [1, 0, 0]}]}
  })");
  c.merge_patch(patch);
  return c;
}

}  // namespace

TEST_CASE("numbers: a stress solve reports converged only within its tolerance", "[hostile][numbers][stress]") {
  const SupportGraph graph = cantilever_graph(2000.0);
  Loads loads;
  loads.gravity = Vec3(0.0, 0.0, -9.81);
  for (const Criterion criterion : {Criterion::von_mises, Criterion::tresca}) {
    for (const bool reference : {false, true}) {
      SpringSolverSettings settings;
      settings.reference = reference;
      const StrengthCriterionModel model(criterion, settings);
      // A plain concrete converges, with its residual inside the tolerance.
      Result<StressResult> plain = model.evaluate(graph, loads, Material{});
      REQUIRE(plain);
      CHECK(plain->report.converged);
      CHECK(plain->report.residual <= plain->report.tolerance);
      CHECK(plain->report.tolerance == solve_tolerance(settings));
      CHECK(convergence_failure(plain->report).empty());
      // Stiffnesses that overflow or vanish in the solve: whatever comes out, converged implies a
      // finite residual within the tolerance and finite figures.
      for (const double e : {1e300, 1e-300, 1e308, 1e-310, 4.9e-324}) {
        INFO("E = " << e << (reference ? " (reference)" : ""));
        Material m;
        m.young_modulus = e;
        Result<StressResult> r = model.evaluate(graph, loads, m);
        REQUIRE(r);
        if (r->report.converged) {
          CHECK(std::isfinite(r->report.residual));
          CHECK(r->report.residual <= r->report.tolerance);
          for (const BondStress& b : r->bonds) CHECK(std::isfinite(b.utilization));
        } else {
          CHECK(convergence_failure(r->report).find("did not converge") != std::string::npos);
        }
      }
      if (!reference) {
        // The block path every command uses: Cholesky per node block, whose factor E = 1e300 ruins
        // (residual about 1): reported converged before; the whole-K reference LDLT solves it exactly.
        Material huge;
        huge.young_modulus = 1e300;
        Result<StressResult> r = model.evaluate(graph, loads, huge);
        REQUIRE(r);
        CHECK_FALSE(r->report.converged);
        CHECK(r->report.residual > r->report.tolerance);
        CHECK(convergence_failure(r->report).find("relative residual") != std::string::npos);
      }
    }
  }
  // The rule itself: a NaN or an over-tolerance residual is never converged.
  for (const double residual : {std::nan(""), 0.94, 1.1e-6, std::numeric_limits<double>::infinity()}) {
    SolverReport report;
    report.residual = residual;
    judge_convergence(report, 1e-6);
    CHECK_FALSE(report.converged);
  }
  // A cascade stops at a solve that did not converge and reports it.
  StrengthCriterionModel model(Criterion::von_mises);
  Material huge;
  huge.young_modulus = 1e300;
  Result<PropagationResult> p = propagate(model, graph, loads, huge, {});
  REQUIRE(p);
  CHECK_FALSE(p->report.converged);
  CHECK(p->rounds == 0);
  // Forces that overflow from finite inputs are refused, not solved.
  Loads heavy;
  heavy.gravity = Vec3(0.0, 0.0, -1e308);
  CHECK_FALSE(model.evaluate(cantilever_graph(1e10), heavy, Material{}));
}

TEST_CASE("numbers: case files refuse physical values outside their documented range", "[hostile][numbers][cases]") {
  const std::vector<std::pair<nlohmann::json, std::string>> bad = {
      {{{"material", {{"young_modulus", 1e300}}}}, "material.young_modulus"},
      {{{"material", {{"young_modulus", 1e-300}}}}, "material.young_modulus"},
      {{{"material", {{"young_modulus", 0.5}}}}, "material.young_modulus"},
      {{{"material", {{"density", 1e300}}}}, "material.density"},
      {{{"material", {{"density", 1e-9}}}}, "material.density"},
      {{{"material", {{"poisson_ratio", 0.5}}}}, "material.poisson_ratio"},
      {{{"material", {{"poisson_ratio", -0.1}}}}, "material.poisson_ratio"},
      {{{"material", {{"tensile_strength", 1e200}}}}, "material.tensile_strength"},
      {{{"material", {{"compressive_strength", 1e-5}}}}, "material.compressive_strength"},
      {{{"material", {{"shear_strength", 1e14}}}}, "material.shear_strength"},
      {{{"gravity", {0, 0, 1e308}}}, "gravity[2]"},
      {{{"gravity", {-2e5, 0, 0}}}, "gravity[0]"},
      {{{"impacts", {{{"frame", 0}, {"point", {1, 0, 0}}, {"direction", {1, 0, 0}}, {"impulse", 1e300}}}}},
       "impacts[0].impulse"},
      {{{"impacts", {{{"frame", 0}, {"point", {1e300, 0, 0}}, {"direction", {1, 0, 0}}, {"impulse", 1}}}}},
       "impacts[0].point[0]"},
      {{{"impacts", {{{"frame", 0}, {"point", {1, 0, 0}}, {"direction", {1, 0, 0}}, {"impulse", 1}, {"radius", 1e200}}}}},
       "impacts[0].radius"},
      {{{"mesh", {{"box", {{"size", {1e300, 0.2, 0.3}}}}}}}, "mesh.box.size[0]"},
      {{{"mesh", {{"box", {{"size", {2, 1e-12, 0.3}}}}}}}, "mesh.box.size[1]"},
      {{{"mesh", {{"box", {{"center", {0, 0, 1e10}}}}}}}, "mesh.box.center[2]"},
      {{{"anchors", {{{"box", {{"min", {-1e300, -1, -1}}, {"max", {0, 1, 1}}}}}}}}, "anchors[0].box.min[0]"},
      {{{"debris", {{"speed", 1e200}}}}, "debris.speed"},
  };
  for (const auto& [patch, key] : bad) {
    const nlohmann::json c = small_case(patch);
    INFO(c.dump());
    Result<Case> r = parse_case(c.dump(), "hostile.json");
    REQUIRE_FALSE(r);
    CHECK(r.error().message.find(key) != std::string::npos);
    CHECK(r.error().message.find('\n') == std::string::npos);
  }
  // Round-trip of the edges: the bounds themselves are accepted, E from gels to diamond.
  for (const double e : {1e3, 3e10, 1e13}) CHECK(parse_case(small_case({{"material", {{"young_modulus", e}}}}).dump(), "ok.json"));
  CHECK(parse_case(small_case({{"material", {{"poisson_ratio", 0.0}}}}).dump(), "ok.json"));
  CHECK(parse_case(small_case({{"gravity", {0, 0, 0}}}).dump(), "ok.json"));

  // Through the CLI: exit 2 and one line naming the key, for the stress command and the grid.
  const fs::path dir = hostile_scratch("cases");
  const fs::path stiff = dir / "stiff.json";
  put_file(stiff, small_case({{"material", {{"young_modulus", 1e300}}}}).dump());
  check_refused(run_cli_argv({"stress", "--case", stiff.string()}), "material.young_modulus");
  const fs::path heavy = dir / "heavy.json";
  put_file(heavy, small_case({{"gravity", {0, 0, -1e308}}}).dump());
  check_refused(run_cli_argv({"stress", "--case", heavy.string(), "--json"}), "gravity[2]");
  check_refused(run_cli_argv({"grid", "--case", heavy.string(), "--no-cache", "--repetitions", "1"}), "gravity[2]");
}

TEST_CASE("numbers: compare judges a zero base by the absolute change and never prints nan or inf",
          "[hostile][numbers][compare]") {
  RunContext ctx;
  ctx.commit = "0123456789ab";
  ctx.cpu_model = "Example CPU";
  ctx.date = "2026-11-22T07:00:00Z";
  ctx.fingerprint = context_fingerprint(ctx);
  // One cell, 10 repetitions; the stress stage takes `base` ms in the base and `next` ms in the new run.
  const auto grid = [](double stage_ms, double jitter) {
    GridResult g;
    g.budget_ms = 33.3;
    g.repetitions = 10;
    g.frames = 2;
    g.same_seed = true;
    GridCell c;
    c.prefracture = 10;
    c.runtime = 5;
    c.prefracturer = c.fracturer = "plane-slice";
    c.stress = "von-mises";
    for (int k = 0; k < g.repetitions; ++k) {
      GridSample s;
      s.seed = 1;
      s.frame_ms = {1.0 + 1e-3 * k, 2.0 + 1e-3 * k};
      s.worst_frame_ms = s.worst_frame_cpu_ms = 2.0 + 1e-3 * k;
      s.stages_ms[static_cast<std::size_t>(Stage::stress)] = stage_ms > 0.0 ? stage_ms + jitter * k : 0.0;
      s.stages_cpu_ms = s.stages_ms;
      c.samples.push_back(s);
    }
    g.cells.push_back(c);
    return g;
  };
  const auto stored = [&](const GridResult& g, const std::string& name) {
    Result<StoredGrid> s = grid_results_from_json(grid_to_json(g, {{"name", "synthetic"}}, ctx), name);
    REQUIRE(s);
    s->path = name;
    return *s;
  };
  struct Pair {
    double base, next;
    Verdict want;
  };
  const std::vector<Pair> pairs = {
      {0.0, 1.35, Verdict::regressed},     // the example: 0 -> 1.35 ms
      {0.0, 0.5, Verdict::regressed},      // any change above --min-change-ms
      {0.0, 0.001, Verdict::same},         // below --min-change-ms
      {4.9e-324, 1.35, Verdict::regressed},// a base so small that new / base overflows
      {1e-300, 2.0, Verdict::regressed},
      {0.0, 0.0, Verdict::same},
  };
  for (const Pair& p : pairs) {
    INFO(p.base << " -> " << p.next);
    CompareOptions o;
    o.clock = "wall";
    const CompareReport report = compare_grids(stored(grid(p.base, 0.0), "base"), stored(grid(p.next, 1e-4), "new"), o);
    bool found = p.base == 0.0 && p.next == 0.0;  // a stage that never ran has no row
    for (const ComparisonRow& r : report.rows)
      if (r.what == "stage stress") {
        found = true;
        CHECK(r.verdict == p.want);
        CHECK(std::isfinite(r.change));
      }
    CHECK(found);
    const std::string md = compare_markdown(report, o);
    CHECK(md.find("nan") == std::string::npos);
    CHECK(md.find("inf") == std::string::npos);
  }

  // A number too large for a double in a results file: compare, merge and report refuse the file.
  const fs::path dir = hostile_scratch("compare");
  const nlohmann::ordered_json good = grid_to_json(grid(1.0, 1e-4), {{"name", "synthetic"}}, ctx);
  const fs::path base = dir / "base.json";
  put_file(base, good.dump());
  for (const std::string key : {"worst_frame_ms", "frame_ms", "calibration_ms"}) {
    std::string text = good.dump();
    const std::string needle = "\"" + key + "\":";
    const std::size_t at = text.find(needle, text.find("\"samples\""));
    REQUIRE(at != std::string::npos);
    std::size_t value = at + needle.size();
    if (text[value] == '[') ++value;
    text.insert(value, "1e999");
    const std::size_t end = text.find_first_of(",]}", value + 5);
    text.erase(value + 5, end - value - 5);
    const fs::path bad = dir / ("bad_" + key + ".json");
    put_file(bad, text);
    INFO(key);
    check_refused(run_cli_argv({"compare", base.string(), bad.string()}), "not finite");
    check_refused(run_cli_argv({"compare", bad.string(), base.string()}), bad.string());
    check_refused(run_cli_argv({"merge", base.string(), bad.string(), "--out", (dir / "m.json").string()}), key);
    check_refused(run_cli_argv({"report", bad.string(), "--out", (dir / "rep").string()}), key);
  }
}

TEST_CASE("numbers: merge refuses one file or one run given twice", "[hostile][numbers][merge]") {
  RunContext ctx;
  ctx.commit = "0123456789ab";
  ctx.date = "2026-11-22T07:00:00Z";
  ctx.fingerprint = context_fingerprint(ctx);
  const auto grid = [](double ms) {
    GridResult g;
    g.budget_ms = 33.3;
    g.repetitions = 1;
    g.frames = 1;
    GridCell c;
    c.prefracture = 10;
    c.runtime = 5;
    c.prefracturer = c.fracturer = "plane-slice";
    c.stress = "von-mises";
    GridSample s;
    s.seed = 1;
    s.frame_ms = {ms};
    s.worst_frame_ms = s.worst_frame_cpu_ms = ms;
    c.samples.push_back(s);
    g.cells.push_back(c);
    summarise_cell(g.cells.back(), g.budget_ms, g.latency_budget_ms);
    return g;
  };
  const fs::path dir = hostile_scratch("merge");
  const fs::path a = dir / "a.json", b = dir / "b.json", copy = dir / "copy.json", hard = dir / "hard.json",
                 link = dir / "link.json";
  put_file(a, grid_to_json(grid(1.0), {{"name", "synthetic"}}, ctx).dump(1));
  put_file(b, grid_to_json(grid(1.2), {{"name", "synthetic"}}, ctx).dump(1));
  fs::copy_file(a, copy);
  fs::create_hard_link(a, hard);
  fs::create_symlink(a, link);
  const fs::path out = dir / "merged.json";
  const std::vector<std::vector<std::string>> twice = {
      {a.string(), a.string()},
      {a.string(), (dir / "." / "a.json").string()},
      {a.string(), hard.string()},
      {a.string(), link.string()},
      {a.string(), copy.string()},  // a copy: the same run
      {b.string(), a.string(), copy.string()},
  };
  for (const bool repetitions : {true, false}) {
    for (const auto& parts : twice) {
      std::vector<std::string> args = {"merge"};
      args.insert(args.end(), parts.begin(), parts.end());
      if (repetitions) args.push_back("--repetitions");
      args.insert(args.end(), {"--out", out.string()});
      INFO(parts.front() << " " << parts.back());
      check_refused(run_cli_argv(args), "merge:");
      CHECK_FALSE(fs::exists(out));
    }
  }
  // Two runs of the same cells join as repetitions.
  const auto ok = run_cli_argv({"merge", a.string(), b.string(), "--repetitions", "--out", out.string()});
  INFO(ok.err);
  CHECK(ok.exit_code == 0);
  Result<StoredGrid> merged = read_grid_results(out);
  REQUIRE(merged);
  CHECK(merged->grid.repetitions == 2);
}

TEST_CASE("numbers: seeds and numeric flags are read strictly on every command", "[hostile][numbers][flags]") {
  // The validator on its own.
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"FLOAT", "nan"},  {"FLOAT", "NaN"},    {"FLOAT", "inf"},         {"FLOAT", "-inf"},  {"FLOAT", "infinity"},
      {"FLOAT", "1e999"}, {"FLOAT", "0x10"},  {"FLOAT", "1.5ms"},       {"FLOAT", ""},      {"FLOAT", " 1"},
      {"INT", "1e3"},    {"INT", "1.0"},      {"INT", "0x10"},          {"INT", "+3"},      {"INT", "9223372036854775808"},
      {"UINT", "-1"},    {"UINT", "18446744073709551616"}, {"UINT", "99999999999999999999999"}, {"UINT", "1e3"},
      {"UINT", " 7"},
  };
  for (const auto& [type, text] : refused) {
    std::string t = text;
    INFO(type << " " << text);
    CHECK_FALSE(cli::numeric_flag_error(type, t).empty());
  }
  std::string octal = "010";
  CHECK(cli::numeric_flag_error("UINT", octal).empty());
  CHECK(octal == "10");  // decimal, not octal 8
  std::string top = "18446744073709551615";
  CHECK(cli::numeric_flag_error("UINT", top).empty());
  std::string neg = "-2.5e-3";
  CHECK(cli::numeric_flag_error("FLOAT", neg).empty());

  // Every command, through the CLI: exit 2, one line naming the flag.
  const fs::path dir = hostile_scratch("flags");
  const fs::path mesh = dir / "box.off";
  put_file(mesh, "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                   "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n"
                   "3 3 0 4\n3 3 4 7\n");
  const std::string j = (dir / "out.json").string();
  struct Bad {
    std::vector<std::string> args;
    std::string flag;
  };
  std::vector<Bad> bad;
  for (const std::string v : {"-1", "18446744073709551616", "1e3", "nan", "0x1"})
    bad.push_back({{"fracture", "--mesh", mesh.string(), "--seed", v}, "--seed"});
  for (const std::string v : {"-1", "1e3", "nan", "99999999999"})
    bad.push_back({{"fracture", "--mesh", mesh.string(), "--fragments", v}, "--fragments"});
  for (const std::string v : {"nan", "inf", "-inf", "NaN"}) {
    bad.push_back({{"fracture", "--mesh", mesh.string(), "--impact", "0.5,0.5,0.5", "--radius", v}, "--radius"});
    bad.push_back({{"fracture", "--mesh", mesh.string(), "--impact", "0.5," + v + ",0.5"}, "--impact"});
    bad.push_back({{"grid", "--case", "building", "--timeout", v, "--json", j}, "--timeout"});
    bad.push_back({{"grid", "--case", "building", "--budget-ms", v, "--json", j}, "--budget-ms"});
    bad.push_back({{"grid", "--case", "building", "--latency-budget-ms", v, "--json", j}, "--latency-budget-ms"});
    bad.push_back({{"stability", "--timeout", v, "--json", j}, "--timeout"});
    bad.push_back({{"compare", j, j, "--max-slowdown", v}, "--max-slowdown"});
    bad.push_back({{"compare", j, j, "--alpha", v}, "--alpha"});
    bad.push_back({{"compare", j, j, "--min-change-ms", v}, "--min-change-ms"});
  }
  for (const std::string v : {"1e3", "-1", "3.0", "99999999999"}) {
    bad.push_back({{"grid", "--case", "building", "--repetitions", v, "--json", j}, "--repetitions"});
    bad.push_back({{"grid", "--case", "building", "--frames", v, "--json", j}, "--frames"});
    bad.push_back({{"grid", "--case", "building", "--prefracture", "10," + v, "--json", j}, "--prefracture"});
    bad.push_back({{"table", "--mesh", mesh.string(), "--repetitions", v}, "--repetitions"});
    bad.push_back({{"table", "--mesh", mesh.string(), "--fragments", v}, "--fragments"});
    bad.push_back({{"accuracy", "--repetitions", v}, "--repetitions"});
    bad.push_back({{"accuracy", "--slabs", v}, "--slabs"});
  }
  for (const Bad& b : bad) {
    INFO(b.args[0] << " " << b.flag << " " << b.args.back());
    check_refused(run_cli_argv(b.args), b.flag);
  }
  CHECK_FALSE(fs::exists(j));
  // The largest seed is a seed.
  const auto top_seed = run_cli_argv({"fracture", "--mesh", mesh.string(), "--fragments", "3", "--seed", "18446744073709551615"});
  INFO(top_seed.err);
  CHECK(top_seed.exit_code == 0);
  // A case's seed: an integer in [0, 2^64 - 1].
  for (const std::string seed : {"-1", "18446744073709551616", "1e3", "1.5", "\"7\""}) {
    const std::string text = R"({"mesh": {"box": {"size": [1, 1, 1]}}, "prefracture": {"seed": )" + seed + "}}";
    INFO(text);
    Result<Case> c = parse_case(text, "seed.json");
    REQUIRE_FALSE(c);
    CHECK(c.error().message.find("prefracture.seed") != std::string::npos);
  }
}

TEST_CASE("numbers: a damaged pre-fracture cache entry is computed again, with the same result",
          "[hostile][numbers][cache]") {
  const fs::path dir = hostile_scratch("cache");
  const fs::path cache = dir / "cache";
  const fs::path case_file = dir / "case.json";
  nlohmann::json c = small_case();
  c.erase("prefracture");
  c["prefracture"] = {{"fracturer", "voronoi"}, {"fragments", 6}, {"seed", 3}};
  c["frames"] = 2;
  put_file(case_file, c.dump());
  const auto run = [&](const std::string& name) {
    std::string file = name;  // the label as a file name: outputs go only into folders that exist
    std::replace(file.begin(), file.end(), '/', '_');
    const fs::path json = dir / (file + ".json");
    const auto r = run_cli_argv({"grid", "--case", case_file.string(), "--prefracture", "6", "--runtime", "2",
                                 "--repetitions", "1", "--cache-dir", cache.string(), "--json", json.string()});
    INFO(name << ": " << r.err);
    CHECK(r.exit_code == 0);
    const nlohmann::json out = nlohmann::json::parse(test::slurp(json), nullptr, false);
    REQUIRE(out.is_object());
    const nlohmann::json& cell = out["cells"][0];
    return std::pair{cell["error"], cell["samples"][0]["cache_hit"].get<bool>()};
  };
  const auto [first, first_hit] = run("first");
  CHECK_FALSE(first_hit);
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(cache)) entries.push_back(e.path());
  REQUIRE(entries.size() == 1);
  const fs::path entry = entries.front();
  const std::string good = test::slurp(entry);
  CHECK(run("hit").second);

  const std::vector<std::pair<std::string, std::function<void()>>> damages = {
      {"truncated", [&] { put_file(entry, good.substr(0, good.size() / 2)); }},
      {"empty", [&] { put_file(entry, ""); }},
      {"garbage", [&] { put_file(entry, std::string(good.size(), '\x5a')); }},
      {"one flipped byte", [&] { std::string d = good; d[d.size() / 2] ^= 0x10; put_file(entry, d); }},
      {"a NaN vertex", [&] { std::string d = good; for (int i = 0; i < 8; ++i) d[200 + i] = '\xff'; put_file(entry, d); }},
      {"wrong version", [&] { std::string d = good; d[7] = '9'; put_file(entry, d); }},
      {"a tail appended", [&] { put_file(entry, good + std::string(100, '\0')); }},
      {"huge (sparse, past the limit)", [&] {
         put_file(entry, good);
         fs::resize_file(entry, (1ULL << 30) + 4096);
       }},
      {"a folder", [&] { fs::remove(entry); fs::create_directory(entry); }},
      {"a FIFO", [&] { fs::remove_all(entry); REQUIRE(::mkfifo(entry.c_str(), 0600) == 0); }},
      {"a link to /dev/zero", [&] { fs::remove_all(entry); fs::create_symlink("/dev/zero", entry); }},
  };
  for (const auto& [what, damage] : damages) {
    INFO(what);
    damage();
    // Both runs succeed with the figures of the first; a regular file is replaced, and then hit.
    const auto [again, again_hit] = run(what + " 1");
    CHECK_FALSE(again_hit);
    CHECK(again == first);
    const auto [next, next_hit] = run(what + " 2");
    CHECK(next == first);
    CHECK(next_hit);  // the damaged entry, whatever it was, was replaced by the recomputed one
    CHECK(fs::is_regular_file(fs::symlink_status(entry)));
    fs::remove_all(entry);
    put_file(entry, good);
  }
}
