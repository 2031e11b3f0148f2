#include "harness/cases/isolated_repair.h"

#include "algorithms/assets/mesh_codec.h"
#include "harness/limits.h"
#include "harness/process/isolated_run.h"
#include "harness/process/resource_limits.h"

#include <fmt/core.h>

namespace shatter {
namespace {

void write_report(BinaryWriter& w, const RepairReport& r) {
  w.value(static_cast<std::uint8_t>(r.repaired));
  for (const int n : {r.vertices_merged, r.faces_removed, r.faces_reoriented, r.holes_filled, r.self_intersections,
                      r.sheets_removed, r.shells, r.cavities})
    w.value(static_cast<std::int32_t>(n));
  for (const double x : {r.hole_area, r.time_ms, r.hausdorff_distance}) w.value(x);
  w.text(r.self_intersection_fix);
}

bool read_report(BinaryReader& rd, RepairReport& r) {
  r.repaired = rd.value<std::uint8_t>() != 0;
  for (int* n : {&r.vertices_merged, &r.faces_removed, &r.faces_reoriented, &r.holes_filled, &r.self_intersections,
                 &r.sheets_removed, &r.shells, &r.cavities})
    *n = rd.value<std::int32_t>();
  for (double* x : {&r.hole_area, &r.time_ms, &r.hausdorff_distance}) *x = rd.value<double>();
  r.self_intersection_fix = rd.text();
  return rd.ok();
}

}  // namespace

Result<RepairedSolid> repair_solid_isolated(const Mesh& mesh, const std::string& what, const RepairBudget& budget) {
  const std::uint64_t memory = budget.memory_bytes > 0 ? budget.memory_bytes : kMaxRepairMemoryBytes;
  const double time_s = budget.time_s > 0.0 ? budget.time_s
                                            : kMaxRepairSeconds * (sanitized_build() ? kSanitizerSlowdown : 1.0);
  // The child answers 'S', the report and the encoded solid, or 'E' and the error's line.
  const IsolatedRun run = run_isolated(
      [&]() -> std::string {
        if (!limit_this_process(memory, time_s)) return "E" + what + ": cannot limit the repair's resources";
        Result<RepairedSolid> repaired = repair_solid(mesh, what);
        if (!repaired) return "E" + repaired.error().message;
        BinaryWriter w;
        w.bytes("S", 1);
        write_report(w, repaired->report);
        const Mesh* one[] = {&repaired->mesh};
        const std::vector<const TextureImage*> images = embedded_images(one);
        write_images(w, images);
        write_mesh(w, repaired->mesh, images);
        return w.data();
      },
      time_s);
  const std::string budget_text = fmt::format("the repair's budget is {:g} s and {:g} MiB", time_s, static_cast<double>(memory >> 20));
  switch (run.end) {
    case IsolatedRun::End::timed_out:
      return Error{fmt::format("{}: the repair ran past its time budget ({}); the mesh is refused", what, budget_text)};
    case IsolatedRun::End::crashed:
      return Error{fmt::format("{}: the repair failed on this mesh ({}; {}); the mesh is refused", what, run.detail,
                               budget_text)};
    case IsolatedRun::End::finished: break;
  }
  if (run.output.empty()) return Error{what + ": the repair gave no answer"};
  if (run.output.front() == 'E') return Error{run.output.substr(1, 2000)};
  BinaryReader r(run.output);
  char tag = 0;
  r.bytes(&tag, 1);
  RepairedSolid out;
  std::vector<std::shared_ptr<const TextureImage>> images;
  if (tag != 'S' || !read_report(r, out.report) || !read_images(r, images) || !read_mesh(r, out.mesh, images) ||
      !r.at_end())
    return Error{what + ": the repair's answer is damaged or incomplete"};
  return out;
}

}  // namespace shatter
