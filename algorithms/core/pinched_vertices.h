#pragma once
/// Pinched vertices: a vertex of a closed mesh where several sheets of triangles meet at one point
/// (two cones touching at their tips). Every edge is still shared by two triangles, but the vertex's
/// triangles form several fans instead of one, so the surface is not a 2-manifold there.

#include "algorithms/core/mesh.h"

namespace shatter {

/// Gives every fan of triangles around a pinched vertex its own copy of the vertex (same position),
/// which makes an edge-manifold mesh a 2-manifold without moving anything. Expects every undirected
/// edge to be used by exactly two triangles in opposite directions. Returns the number of vertices
/// added.
int split_pinched_vertices(Mesh& mesh);

}  // namespace shatter
