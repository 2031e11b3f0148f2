#include "harness/stability/stress_hazards.h"

#include "algorithms/stress/propagation.h"

#include <cmath>

namespace shatter {
namespace {

constexpr double kBlock = 0.2;       // m, edge of one cubic block
constexpr double kDensity = 2400.0;  // kg/m^3

/// A vertical column of `count` cubic blocks on the z axis, bonded face to face; `anchor_bottom` and
/// `anchor_top` fix the end blocks.
SupportGraph column(int count, bool anchor_bottom, bool anchor_top) {
  SupportGraph g;
  const double volume = kBlock * kBlock * kBlock;
  for (int i = 0; i < count; ++i) {
    SupportNode n;
    n.volume = volume;
    n.mass = kDensity * volume;
    n.centroid = Vec3(0, 0, (i + 0.5) * kBlock);
    n.inertia = Eigen::Matrix3d::Identity() * (n.mass * kBlock * kBlock / 6.0);
    n.anchored = (anchor_bottom && i == 0) || (anchor_top && i == count - 1);
    g.nodes.push_back(n);
  }
  g.node_bonds.resize(static_cast<std::size_t>(count));
  for (int i = 0; i + 1 < count; ++i) {
    Bond b;
    b.a = i;
    b.b = i + 1;
    b.area = kBlock * kBlock;
    b.centroid = Vec3(0, 0, (i + 1) * kBlock);
    b.normal = Vec3::UnitZ();
    b.axis_1 = Vec3::UnitX();
    b.axis_2 = Vec3::UnitY();
    b.moment_1 = b.moment_2 = std::pow(kBlock, 4) / 12.0;
    b.polar_moment = b.moment_1 + b.moment_2;
    b.fibre_1 = b.fibre_2 = kBlock / 2.0;
    b.radius = kBlock / std::sqrt(2.0);
    b.length = kBlock;
    g.node_bonds[static_cast<std::size_t>(i)].push_back(static_cast<int>(g.bonds.size()));
    g.node_bonds[static_cast<std::size_t>(i + 1)].push_back(static_cast<int>(g.bonds.size()));
    g.bonds.push_back(b);
  }
  return g;
}

/// Scales a bond's section by `factor` in area (lengths by sqrt(factor)).
void shrink_bond(Bond& b, double factor) {
  const double s = std::sqrt(factor);
  b.area *= factor;
  b.moment_1 *= factor * factor;
  b.moment_2 *= factor * factor;
  b.polar_moment *= factor * factor;
  b.fibre_1 *= s;
  b.fibre_2 *= s;
  b.radius *= s;
}

StressHazard hazard(std::string name, std::string description, SupportGraph graph) {
  StressHazard h;
  h.name = std::move(name);
  h.description = std::move(description);
  h.graph = std::move(graph);
  return h;
}

bool finite(const BondStress& s) {
  return std::isfinite(s.normal_force) && std::isfinite(s.shear_force) && std::isfinite(s.bending_moment) &&
         std::isfinite(s.torsion) && std::isfinite(s.sigma) && std::isfinite(s.tau) && std::isfinite(s.utilization);
}

bool same(const PropagationResult& x, const PropagationResult& y) {
  if (x.result.bonds.size() != y.result.bonds.size() || x.break_order != y.break_order) return false;
  for (std::size_t i = 0; i < x.result.bonds.size(); ++i) {
    const BondStress& a = x.result.bonds[i];
    const BondStress& b = y.result.bonds[i];
    if (a.broken != b.broken || a.sigma != b.sigma || a.tau != b.tau || a.utilization != b.utilization) return false;
  }
  return x.result.displacements == y.result.displacements;
}

}  // namespace

std::vector<StressHazard> stress_hazards(bool quick) {
  std::vector<StressHazard> out;
  // A column held at both ends is statically indeterminate: the stiffness ratio decides the load path.
  SupportGraph stiff = column(20, true, true);
  for (std::size_t i = 0; i < stiff.bonds.size(); ++i) stiff.bonds[i].length *= (i % 2 == 0) ? 1e-4 : 1e4;
  out.push_back(hazard("stiffness-ratio-1e8", "column of 20 blocks held at both ends, bond stiffnesses 1e8 apart",
                       std::move(stiff)));
  SupportGraph tiny = column(20, true, true);
  shrink_bond(tiny.bonds[10], 1e-12);
  out.push_back(hazard("tiny-bond", "column of 20 blocks held at both ends, one bond of 1e-12 of the mean area",
                       std::move(tiny)));
  out.push_back(hazard("no-anchor", "column of 20 blocks with no anchor", column(20, false, false)));
  const int chain = quick ? 1000 : 10000;
  out.push_back(hazard("chain-" + std::to_string(chain),
                       "column of " + std::to_string(chain) + " blocks anchored at the bottom", column(chain, true, false)));
  StressHazard still = hazard("zero-gravity", "column of 20 blocks anchored at the bottom, no gravity",
                              column(20, true, false));
  still.loads.gravity = Vec3::Zero();
  out.push_back(std::move(still));
  return out;
}

HazardResult run_stress_hazard(const StressHazard& h, const std::string& model, const Registries& registries) {
  HazardResult r;
  r.hazard = h.name;
  r.algorithm = model;
  r.kind = "stress";
  r.fragments = h.graph.node_count();
  Result<std::unique_ptr<StressModel>> m = registries.stress_models.create(model);
  if (!m) {
    r.outcome = refusal_outcome(m.error());
    r.detail = m.error().message;
    return r;
  }
  const Material material;
  Result<PropagationResult> first = propagate(**m, h.graph, h.loads, material);
  if (!first) {
    r.outcome = refusal_outcome(first.error());
    r.detail = first.error().message;
    return r;
  }
  r.converged = first->report.converged;
  r.residual = first->report.residual;
  r.iterations = first->report.iterations;
  r.worst_error = r.residual;
  r.outcome = HazardOutcome::invalid_output;
  for (std::size_t i = 0; i < first->result.bonds.size(); ++i)
    if (!finite(first->result.bonds[i])) {
      r.detail = "bond " + std::to_string(i) + ": NaN or Inf";
      return r;
    }
  for (const double d : first->result.displacements)
    if (!std::isfinite(d)) {
      r.detail = "NaN or Inf displacement";
      return r;
    }
  if (!std::isfinite(r.residual)) {
    r.detail = "NaN or Inf residual";
    return r;
  }
  if (!r.converged) {
    r.detail = "solver did not converge (residual " + std::to_string(r.residual) + ")";
    return r;
  }
  Result<PropagationResult> second = propagate(**m, h.graph, h.loads, material);
  if (!second || !same(*first, *second)) {
    r.detail = "not deterministic: a second run gave different stresses";
    return r;
  }
  r.outcome = HazardOutcome::valid;
  return r;
}

}  // namespace shatter
