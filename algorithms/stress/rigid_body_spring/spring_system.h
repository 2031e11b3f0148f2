#pragma once
/// The static solve of the rigid-body-spring model for one anchored component of a support graph.
///
/// Design note: every fragment is a rigid body with 6 unknowns, its translation u (m) and small
/// rotation theta (rad) about its centroid. Every intact bond is a zero-length spring set at the bond
/// centroid p, in the bond frame (n, axis_1, axis_2): normal stiffness E A / L, shear G A / L, bending
/// E I_1 / L and E I_2 / L about the principal axes, torsion G J / L, with L the bond's characteristic
/// length (centroid a -> plane -> centroid b). The relative motion across the bond is
///   delta = (u_b + theta_b x (p - x_b)) - (u_a + theta_a x (p - x_a)),  phi = theta_b - theta_a,
/// and the spring forces acting on b are -K_t delta and -K_r phi. Anchored bodies have no unknowns.
/// Both spring forces act at p, so each body's equilibrium K u = f is exact statics: where the
/// structure is statically determinate the bond forces are those of equilibrium, whatever E, G and L.
/// The matrix is assembled straight into compressed columns (the pattern is the graph's, without the
/// entries every bond leaves zero: stiffness_pattern.h).

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/material.h"
#include "algorithms/stress/rigid_body_spring/bond_spring.h"
#include "algorithms/stress/rigid_body_spring/bond_stiffness_cache.h"
#include "algorithms/stress/rigid_body_spring/linear_solve.h"
#include "algorithms/stress/stress_model.h"

#include <span>
#include <vector>

namespace shatter {

/// External force and moment (about the centroid) on every node: 6 #nodes, N and N m.
std::vector<double> node_loads(const SupportGraph& graph, const Loads& loads, const Material& material);

/// Solves the component made of `nodes` (with at least one anchored) and its intact `bonds`.
/// `displacements` (6 #nodes, global) is read as the warm start of the component's nodes and
/// overwritten with the solution; `forces` (#bonds, global) receives the forces of `bonds`. The solve
/// reuses and keeps its work in `memory` (linear_solve.h), and takes the bonds' springs and blocks from
/// `stiffness` when given (same numbers, computed once per bond: bond_stiffness_cache.h).
SolverReport solve_component(const SupportGraph& graph, std::span<const int> nodes, std::span<const int> bonds,
                             std::span<const double> loads, const Material& material,
                             const SpringSolverSettings& settings, SolverMemory& memory,
                             std::vector<double>& displacements, std::vector<BondForces>& forces,
                             BondStiffnessCache* stiffness = nullptr);

}  // namespace shatter
