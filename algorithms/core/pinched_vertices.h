#pragma once
/// Pinched vertices and edges: places of a closed mesh where several sheets of triangles meet. At a
/// pinched vertex (two cones touching at their tips) every edge is still shared by two triangles, but
/// the vertex's triangles form several fans instead of one. At a pinched edge (two volumes touching
/// along an edge, as CGAL's orient_polygon_soup outputs them) 2k triangles share one edge, k in each
/// direction. Either way the surface is not a 2-manifold there, though it bounds a valid solid.
///
/// Design note: around a pinched edge the triangles are ordered by the angle of their half-plane about
/// the edge; a triangle's outward normal points towards increasing angle when it runs along the edge's
/// direction, so the material next to it lies towards decreasing angle, up to the neighbouring
/// triangle running the other way. Each such pair is one manifold sheet through the edge. Sheets are
/// then separated exactly as at a pinched vertex: every fan of corners around a vertex (corners linked
/// through the twin of each edge, the paired triangle at a pinched edge) gets its own copy of the vertex.

#include "algorithms/core/mesh.h"

namespace shatter {

/// How many pinched places split_pinched_vertices separated.
struct PinchSplit {
  int added_vertices = 0;  ///< copies of vertices made (same positions)
  int split_edges = 0;     ///< undirected edges used by 2k > 2 triangles, paired into k sheets
};

/// Gives every sheet through a pinched vertex or edge its own copies of the vertices (see the design
/// note), which makes the mesh a 2-manifold without moving anything. Needs every undirected edge used
/// by an even number of triangles, half in each direction, whose half-planes about the edge
/// alternate in direction by angle; otherwise the mesh is left unchanged (and nothing is reported).
PinchSplit split_pinched_vertices(Mesh& mesh);

}  // namespace shatter
