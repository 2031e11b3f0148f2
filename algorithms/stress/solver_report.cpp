// The convergence rule of the stress solves and the sums of their reports (declared in stress_model.h).
#include "algorithms/stress/stress_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace shatter {

void judge_convergence(SolverReport& report, double tolerance) {
  report.tolerance = tolerance;
  // A NaN residual compares false: never converged.
  report.converged = report.converged && std::isfinite(report.residual) && report.residual <= tolerance;
}

void add_solver_report(SolverReport& total, const SolverReport& r) {
  total.solves += r.solves;
  total.iterations += r.iterations;
  total.converged = total.converged && r.converged;
  total.finite = total.finite && r.finite;
  // std::max keeps the first argument when the second is NaN: a NaN residual must win.
  total.residual = std::isnan(r.residual) ? r.residual : std::max(total.residual, r.residual);
  total.tolerance = std::max(total.tolerance, r.tolerance);
  total.unknowns = std::max(total.unknowns, r.unknowns);
}

std::string convergence_failure(const SolverReport& report) {
  if (report.converged) return {};
  if (!report.finite) return "the solve did not converge (it gave non-finite forces or displacements)";
  char line[160];
  std::snprintf(line, sizeof line, "the solve did not converge (relative residual %.3g > tolerance %.3g)",
                report.residual, report.tolerance);
  return line;
}

Status check_node_loads(std::span<const double> node_loads) {
  for (std::size_t i = 0; i < node_loads.size(); ++i)
    if (!std::isfinite(node_loads[i]))
      return Error{"loads: the load on fragment " + std::to_string(i / 6) +
                   " is not finite (gravity times the fragment's mass overflows)"};
  return {};
}

bool values_finite(std::span<const double> values) {
  unsigned bad = 0;
  for (const double d : values) bad |= nonfinite_bit(d);
  return bad == 0;
}

bool judge_finite(StressResult& result) {
  bool finite = values_finite(result.displacements);
  for (const BondStress& b : result.bonds) finite &= bond_finite(b);
  if (!finite) {
    result.report.finite = false;
    result.report.converged = false;
  }
  return finite;
}

}  // namespace shatter
