#include "harness/accuracy/beam_reference.h"

#include "algorithms/core/primitives.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shatter {
namespace {

/// The coordinate axis `v` lies along, or -1.
int axis_of(const Vec3& v) {
  const double n = v.norm();
  if (!(n > 0.0)) return -1;
  for (int a = 0; a < 3; ++a)
    if (std::abs(std::abs(v[a]) / n - 1.0) < 1e-12) return a;
  return -1;
}

double low(const BeamReference& r) { return r.center[r.axis] - r.size[r.axis] / 2; }
double high(const BeamReference& r) { return r.center[r.axis] + r.size[r.axis] / 2; }
double span(const BeamReference& r) { return r.size[r.axis]; }

double relative(double value, double truth) { return std::abs(value - truth) / std::abs(truth); }

/// The bond whose centroid lies at `x` along the axis (within 1e-6 of the span), or -1.
int bond_at(const BeamReference& r, const SupportGraph& g, double x) {
  for (int i = 0; i < g.bond_count(); ++i)
    if (std::abs(g.bonds[static_cast<std::size_t>(i)].centroid[r.axis] - x) < 1e-6 * span(r)) return i;
  return -1;
}

/// Distance of a position along the axis from the free end (cantilever, column).
double from_free_end(const BeamReference& r, double x) { return r.anchored_at_min ? high(r) - x : x - low(r); }

/// A region holding every point within `reach` of the box in the two other axes, and [lo, hi] along the axis.
Aabb slab_region(const BeamReference& r, double lo, double hi) {
  Vec3 min = r.center - r.size, max = r.center + r.size;
  min[r.axis] = lo;
  max[r.axis] = hi;
  Aabb box;
  box.extend(min);
  box.extend(max);
  return box;
}

}  // namespace

const char* beam_kind_name(BeamKind kind) {
  switch (kind) {
    case BeamKind::cantilever: return "cantilever";
    case BeamKind::column: return "column";
    case BeamKind::fixed_beam: return "fixed-beam";
  }
  return "?";
}

std::optional<BeamReference> classify_beam_case(const Case& c) {
  const auto* box = std::get_if<BoxSpec>(&c.mesh);
  if (!box || !c.prefracture.explicit_planes() || c.anchors.empty()) return std::nullopt;
  BeamReference r;
  r.size = box->size;
  r.center = box->center;
  r.density = c.material.density;
  r.g = c.gravity.norm();
  r.gravity_axis = axis_of(c.gravity);
  r.axis = axis_of(c.prefracture.planes.front().normal);
  if (r.gravity_axis < 0 || r.axis < 0) return std::nullopt;
  for (const Plane& p : c.prefracture.planes)
    if (axis_of(p.normal) != r.axis) return std::nullopt;
  bool at_min = false, at_max = false;
  for (const Aabb& a : c.anchors) {
    const double quarter = span(r) / 4;
    if (a.max[r.axis] < low(r) + quarter) at_min = true;
    else if (a.min[r.axis] > high(r) - quarter) at_max = true;
    else return std::nullopt;
  }
  if (at_min && at_max) {
    if (r.axis == r.gravity_axis) return std::nullopt;
    r.kind = BeamKind::fixed_beam;
    return r;
  }
  r.anchored_at_min = at_min;
  if (r.axis != r.gravity_axis) {
    r.kind = BeamKind::cantilever;
    return r;
  }
  // A column stands on its held end: gravity points from the free end towards it.
  const bool gravity_down_axis = c.gravity[r.axis] < 0.0;
  if (gravity_down_axis != at_min) return std::nullopt;
  r.kind = BeamKind::column;
  return r;
}

Result<SupportGraph> beam_structure(const BeamReference& ref, int slabs, const PlaneCutting& cutter) {
  if (slabs < 2) return Error{"slabs: must be >= 2"};
  const double lo = low(ref), hi = high(ref), l = span(ref);
  std::vector<Plane> planes;
  const auto cut = [&](double x) {
    Plane p;
    p.point = ref.center;
    p.point[ref.axis] = x;
    p.normal = Vec3::Unit(ref.axis);
    planes.push_back(p);
  };
  Vec3 size = ref.size;
  std::vector<Aabb> anchors;
  if (ref.kind == BeamKind::fixed_beam) {
    const double t = 1e-5 * l;
    size[ref.axis] += 2 * t;
    cut(lo);
    for (int i = 1; i < slabs; ++i) cut(lo + l * i / slabs);
    cut(hi);
    anchors = {slab_region(ref, lo - l, lo - t / 2), slab_region(ref, hi + t / 2, hi + l)};
  } else {
    for (int i = 1; i < slabs; ++i) cut(lo + l * i / slabs);
    const double reach = 1e-3 * l / slabs;
    anchors = {ref.anchored_at_min ? slab_region(ref, lo - l, lo + reach) : slab_region(ref, hi - reach, hi + l)};
  }
  Result<std::vector<Fragment>> fragments = cutter.cut_by_planes(make_box(size, ref.center), planes);
  if (!fragments) return fragments.error();
  SupportGraphSettings settings;
  settings.density = ref.density;
  return build_support_graph(*fragments, anchors, settings);
}

double beam_error(const BeamReference& ref, const SupportGraph& graph, const StressResult& result) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int other_1 = (ref.axis + 1) % 3 == ref.gravity_axis ? (ref.axis + 2) % 3 : (ref.axis + 1) % 3;
  const double h = ref.size[ref.gravity_axis], b = ref.size[other_1];
  const double area = b * h;
  const double w = ref.density * ref.g * area;  // N/m
  const double inertia = b * h * h * h / 12.0;
  double worst = 0.0;
  switch (ref.kind) {
    case BeamKind::cantilever:
      if (graph.bond_count() == 0) return nan;
      for (int i = 0; i < graph.bond_count(); ++i) {
        const double s = from_free_end(ref, graph.bonds[static_cast<std::size_t>(i)].centroid[ref.axis]);
        const double moment = w * s * s / 2.0;
        const BondStress& bs = result.bonds[static_cast<std::size_t>(i)];
        worst = std::max({worst, relative(bs.bending_moment, moment), relative(bs.sigma, moment * (h / 2) / inertia)});
      }
      return worst;
    case BeamKind::column:
      if (graph.bond_count() == 0) return nan;
      for (int i = 0; i < graph.bond_count(); ++i) {
        const double s = from_free_end(ref, graph.bonds[static_cast<std::size_t>(i)].centroid[ref.axis]);
        worst = std::max(worst, relative(result.bonds[static_cast<std::size_t>(i)].sigma, ref.density * ref.g * s));
      }
      return worst;
    case BeamKind::fixed_beam: {
      const double l = span(ref);
      const int ends[] = {bond_at(ref, graph, low(ref)), bond_at(ref, graph, high(ref))};
      const int mid = bond_at(ref, graph, low(ref) + l / 2);
      if (ends[0] < 0 || ends[1] < 0 || mid < 0) return nan;
      for (const int e : ends)
        worst = std::max(worst, relative(result.bonds[static_cast<std::size_t>(e)].bending_moment, w * l * l / 12.0));
      return std::max(worst, relative(result.bonds[static_cast<std::size_t>(mid)].bending_moment, w * l * l / 24.0));
    }
  }
  return nan;
}

std::vector<int> beam_first_failure(const BeamReference& ref, const SupportGraph& graph) {
  if (ref.kind == BeamKind::fixed_beam) {
    std::vector<int> out;
    for (const double x : {low(ref), high(ref)})
      if (const int i = bond_at(ref, graph, x); i >= 0) out.push_back(i);
    return out;
  }
  int best = -1;
  double best_s = -1.0;
  for (int i = 0; i < graph.bond_count(); ++i) {
    const double s = from_free_end(ref, graph.bonds[static_cast<std::size_t>(i)].centroid[ref.axis]);
    if (s > best_s) {
      best_s = s;
      best = i;
    }
  }
  return best < 0 ? std::vector<int>{} : std::vector<int>{best};
}

}  // namespace shatter
