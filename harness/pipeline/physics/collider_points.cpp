#include "harness/pipeline/physics/collider_points.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace shatter {
namespace {

/// The 26 directions of a cube's faces, corners and edges (unnormalised: only argmax is needed).
constexpr std::array<std::array<double, 3>, 26> kCubeDirections{{
    {1, 0, 0},  {-1, 0, 0}, {0, 1, 0},   {0, -1, 0},  {0, 0, 1},   {0, 0, -1},  {1, 1, 1},
    {-1, -1, -1}, {1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {-1, 1, -1}, {-1, 1, 1}, {1, -1, -1},
    {1, 1, 0},  {-1, -1, 0}, {1, -1, 0},  {-1, 1, 0},  {1, 0, 1},   {-1, 0, -1}, {1, 0, -1},
    {-1, 0, 1}, {0, 1, 1},   {0, -1, -1}, {0, 1, -1},  {0, -1, 1},
}};

/// Point k of a spherical Fibonacci set of n points.
Vec3 fibonacci_direction(int k, int n) {
  const double z = 1.0 - (2.0 * k + 1.0) / n;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * std::numbers::pi * k / std::numbers::phi;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

/// The directions after the cube's for a budget: a spherical Fibonacci set of 8 x budget points in a
/// strided order (a step coprime with n near n / phi^2), so that every prefix is spread from pole to
/// pole. The same for every piece: made once per budget and thread (pieces are planned on workers).
const std::vector<Vec3>& fill_directions(int budget) {
  thread_local std::vector<Vec3> directions;
  thread_local int made_for = -1;
  if (made_for != budget) {
    const int n = 8 * budget;
    int step = std::max(1, static_cast<int>(n * 0.3819660112501051));
    while (std::gcd(step, n) != 1) ++step;
    directions.clear();
    for (int j = 0; j < n; ++j)
      directions.push_back(fibonacci_direction(static_cast<int>((static_cast<long>(j) * step) % n), n));
    made_for = budget;
  }
  return directions;
}

}  // namespace

std::vector<std::int32_t> collider_point_indices(std::span<const Vec3> points, int budget) {
  std::vector<std::int32_t> out;
  if (static_cast<int>(points.size()) <= budget) {
    out.resize(points.size());
    std::iota(out.begin(), out.end(), 0);
    return out;
  }
  std::vector<char> taken(points.size(), 0);
  out.reserve(static_cast<std::size_t>(budget));
  const auto take_extreme = [&](const Vec3& d) {
    std::size_t best = 0;
    double best_dot = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double s = d.dot(points[i]);
      if (s > best_dot) {
        best_dot = s;
        best = i;
      }
    }
    if (!taken[best]) {
      taken[best] = 1;
      out.push_back(static_cast<std::int32_t>(best));
    }
  };
  for (const auto& d : kCubeDirections) {
    if (static_cast<int>(out.size()) >= budget) return out;
    take_extreme(Vec3(d[0], d[1], d[2]));
  }
  // More directions until the budget is filled (a few points may be extreme along none of them,
  // which leaves the collider under its budget).
  for (const Vec3& d : fill_directions(budget)) {
    if (static_cast<int>(out.size()) >= budget) break;
    take_extreme(d);
  }
  return out;
}

std::vector<std::int32_t> collider_vertex_indices(const Mesh& mesh, const VertexPlanes& planes,
                                                  bool drop_inner_points, int budget) {
  std::vector<std::int32_t> chosen;
  if (drop_inner_points) chosen = outer_point_indices(mesh, planes);
  // A piece flat to within the tolerance can keep only the corners of its outline: every point then.
  if (chosen.size() < 4) {
    chosen.resize(mesh.vertices.size());
    std::iota(chosen.begin(), chosen.end(), 0);
  }
  if (budget <= 0) return chosen;
  std::vector<Vec3> candidates;
  candidates.reserve(chosen.size());
  for (const std::int32_t v : chosen) candidates.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  std::vector<std::int32_t> within;
  for (const std::int32_t k : collider_point_indices(candidates, budget)) within.push_back(chosen[static_cast<std::size_t>(k)]);
  return within;
}

}  // namespace shatter
