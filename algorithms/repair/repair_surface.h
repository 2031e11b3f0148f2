#pragma once
/// The surface type the repair steps share: a CGAL Surface_mesh in double precision whose faces each
/// remember the input triangle they come from, so that tags survive every step.
///
/// Design note: the repair's steps (soup cleaning, stitching, hole filling, autorefinement, wrapping)
/// create, split and delete faces. A face property `f:origin` holds the index of the input triangle a
/// face is (a piece of), or -1 for a face the repair made; the steps that split faces copy it to the
/// pieces, and the conversion back to a Mesh turns it into the input's tag or FaceTag::repair. Only the
/// repair's translation units include this header (CGAL stays out of the rest of the tree).

#include "algorithms/core/mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <vector>

namespace shatter::repair {

/// Kernel of the repair's surfaces: exact predicates, double constructions.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
/// A point of a repair surface, m.
using Point = Kernel::Point_3;
/// The halfedge surface every repair step works on.
using SurfaceMesh = CGAL::Surface_mesh<Point>;
/// A face of a SurfaceMesh.
using FaceIndex = SurfaceMesh::Face_index;
/// Per face: the input triangle it comes from, or -1 for a face the repair made.
using OriginMap = SurfaceMesh::Property_map<FaceIndex, std::int32_t>;

/// The origin map of `mesh`, created (all -1) when missing.
inline OriginMap origin_map(SurfaceMesh& mesh) {
  return mesh.add_property_map<FaceIndex, std::int32_t>("f:origin", -1).first;
}

/// The surface as a Mesh: vertices in index order (removed and isolated ones skipped), faces tagged with the
/// tag of their origin in `input_tags` (surface when it has none), or FaceTag::repair for faces the repair made. With `origins`,
/// also each triangle's origin (#F, -1 for a new face).
Mesh to_mesh(SurfaceMesh& surface, const std::vector<FaceTag>& input_tags, std::vector<std::int32_t>* origins = nullptr);

/// A closed Mesh as a surface (faces keep their order; origins from `origins`, one per triangle).
SurfaceMesh to_surface(const Mesh& mesh, const std::vector<std::int32_t>& origins);

}  // namespace shatter::repair
