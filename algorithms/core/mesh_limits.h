#pragma once
/// The documented limits of the mesh readers (docs/limits.md): an input past one is refused with an
/// error naming the file, the line and the limit, before the memory it would need is allocated.
///
/// Design note: the numbers are far above any mesh a real-time destruction benchmark fractures (the
/// CGAL data set's largest is under a million triangles; a game asset is well under that) and far
/// below what would exhaust a benchmark machine: a mesh at the limits holds about 370 MB of vertices,
/// indices and tags, and validation and fracture need a small multiple of that. A limit catches a corrupt
/// header or a wrong file, not a mesh someone meant to use.

#include <cstdint>

namespace shatter {

/// Triangles per mesh, counted after polygons are triangulated (12 bytes of indices and a tag each).
inline constexpr std::int64_t kMaxMeshTriangles = 10'000'000;

/// Vertices per mesh, unreferenced ones included (24 bytes each).
inline constexpr std::int64_t kMaxMeshVertices = 10'000'000;

/// Size of a mesh file in bytes: the readers hold the whole text in memory. A file at the triangle
/// and vertex limits written with full double precision takes about 1 GB.
inline constexpr std::uint64_t kMaxMeshFileBytes = 2ULL << 30;

/// Corners of one polygon face (OFF or OBJ). The triangulation is O(n log n) (polygon_triangulation.h);
/// the limit bounds the time and scratch memory one face line can ask for (docs/limits.md gives the
/// measured time at the limit).
inline constexpr std::int64_t kMaxPolygonCorners = 1'000'000;

/// The limits one read applies; the defaults are the documented ones (tests pass smaller ones).
struct MeshReadLimits {
  std::int64_t max_triangles = kMaxMeshTriangles;    ///< triangles after triangulation
  std::int64_t max_vertices = kMaxMeshVertices;      ///< vertices
  std::uint64_t max_file_bytes = kMaxMeshFileBytes;  ///< bytes of the file
};

}  // namespace shatter
