#pragma once
/// Test and benchmark structures: boxes pre-fractured by explicit planes into slabs or blocks, with
/// their support graphs. Their truths (beam theory, statics) are in the tests, not here.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"

#include <cassert>
#include <vector>

namespace shatter::test {

/// Axis-aligned box from its corners, m.
inline Aabb box_region(const Vec3& min, const Vec3& max) {
  Aabb b;
  b.extend(min);
  b.extend(max);
  return b;
}

/// The fragments of an axis-aligned box of `size` centred at `center`, cut by `planes`.
inline std::vector<Fragment> sliced_box(const Vec3& size, const Vec3& center, const std::vector<Plane>& planes) {
  const PlaneSliceFracturer slicer;
  Result<std::vector<Fragment>> fragments = slicer.fracture_by_planes(make_box(size, center), planes);
  assert(fragments.ok());
  return std::move(fragments.value());
}

/// Planes normal to axis `axis` at the given coordinates.
inline std::vector<Plane> planes_at(int axis, const std::vector<double>& positions) {
  std::vector<Plane> out;
  for (const double p : positions) {
    Plane plane;
    plane.point = Vec3::Zero();
    plane.point[axis] = p;
    plane.normal = Vec3::Unit(axis);
    out.push_back(plane);
  }
  return out;
}

/// `count` - 1 evenly spaced positions strictly inside [begin, end].
inline std::vector<double> even_cuts(double begin, double end, int count) {
  std::vector<double> out;
  for (int i = 1; i < count; ++i) out.push_back(begin + (end - begin) * i / count);
  return out;
}

/// Support graph of fragments, at `density`, with the given anchor regions.
inline SupportGraph graph_of(const std::vector<Fragment>& fragments, const std::vector<Aabb>& anchors,
                             double density) {
  SupportGraphSettings settings;
  settings.density = density;
  Result<SupportGraph> graph = build_support_graph(fragments, anchors, settings);
  assert(graph.ok());
  return std::move(graph.value());
}

/// A wall of nx x nz blocks (x along the wall, z up, one block thick), its bottom row anchored. The
/// blocks are separate boxes (slicing a box by ~140 planes into 5,000 pieces is slow and not what the
/// stress benchmarks measure), so every face is offered to the bond finder.
inline SupportGraph block_wall(int nx, int nz, double block = 0.5, double thickness = 0.3, double density = 2400.0) {
  std::vector<Fragment> fragments;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      Fragment f;
      f.mesh = make_box({block, thickness, block}, {(i + 0.5) * block, 0.0, (k + 0.5) * block});
      f.mass.volume = block * thickness * block;
      f.mass.centroid = Vec3((i + 0.5) * block, 0.0, (k + 0.5) * block);
      f.mass.inertia = Vec3(thickness * thickness + block * block, 2 * block * block,
                            thickness * thickness + block * block).asDiagonal() * (f.mass.volume / 12.0);
      fragments.push_back(std::move(f));
    }
  SupportGraphSettings settings;
  settings.density = density;
  settings.all_faces = true;
  Result<SupportGraph> graph = build_support_graph(
      fragments, std::vector<Aabb>{box_region({-1.0, -1.0, -1.0}, {nx * block + 1.0, 1.0, 0.25 * block})}, settings);
  assert(graph.ok() && graph->bond_count() == (nx - 1) * nz + nx * (nz - 1));
  return std::move(graph.value());
}

}  // namespace shatter::test
