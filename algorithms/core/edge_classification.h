#pragma once
/// How the edges of a triangle mesh are used, and exact collinearity of a triangle's corners: the
/// combinatorial and degeneracy parts of the acceptance rule (solid_check.h).

#include "algorithms/core/mesh.h"

#include <cstdint>
#include <vector>

namespace shatter {

/// How the undirected edge under one directed triangle edge is used.
enum class EdgeState : std::uint8_t {
  ok,            ///< two triangles, opposite directions
  open,          ///< one triangle (a hole's border)
  non_manifold,  ///< more than two triangles
  misoriented,   ///< two triangles, one direction
};

/// Per directed edge 3 f + i (corner i to corner i + 1 of triangle f): the state of its undirected
/// edge, how many triangles use it and how many of them run from its lower to its higher vertex.
struct EdgeClassification {
  std::vector<EdgeState> state;
  std::vector<std::int32_t> uses;
  std::vector<std::int32_t> forwards;
};

/// Classifies every edge of `triangles` (indices below `vertex_count`). Buckets the directed edges by
/// their lower vertex (counting sort) and sorts each small bucket by the upper vertex, so that the
/// uses of one undirected edge are adjacent. O(#F).
EdgeClassification classify_edges(const std::vector<Triangle>& triangles, std::size_t vertex_count);

/// True when a, b, c are exactly collinear: all three coordinate-plane projections have zero area
/// (exact predicate on the stored doubles).
bool exactly_collinear(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace shatter
