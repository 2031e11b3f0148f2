#pragma once
/// The support graph: fragments as nodes, the faces two fragments share as bonds, plus anchors.
///
/// Design note: bonds are found from geometry alone (coincident, opposite faces), never from how the
/// fragments were made, so fragments from any fracturer, or read back from files, get the same bonds.
/// A bond is one planar contact region between two fragments; two fragments touching on two different
/// planes (possible for non-convex pieces) get two bonds. Each bond carries what a beam section needs:
/// area, centroid, normal, principal second moments and extreme fibre distances, so a stress model
/// never goes back to the meshes. Nodes keep their mass properties at the material's density; the
/// graph is immutable once built, and models keep any per-solve state (broken flags, displacements)
/// outside it.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/core/fragment.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace shatter {

/// One fragment as a rigid body.
struct SupportNode {
  double volume = 0.0;                                  ///< m^3
  double mass = 0.0;                                    ///< kg (density * volume)
  Vec3 centroid = Vec3::Zero();                         ///< m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();    ///< kg m^2, about the centroid
  bool anchored = false;                                ///< fixed to the world (overlaps an anchor)
};

/// One planar contact between fragments a < b, with its section properties.
struct Bond {
  int a = 0;                          ///< fragment index (the smaller)
  int b = 0;                          ///< fragment index (the larger)
  double area = 0.0;                  ///< contact area, m^2
  Vec3 centroid = Vec3::Zero();       ///< centroid of the contact region, m
  Vec3 normal = Vec3::UnitX();        ///< unit normal of the contact plane, pointing from a to b
  Vec3 axis_1 = Vec3::UnitY();        ///< unit principal axis of the larger second moment, in the plane
  Vec3 axis_2 = Vec3::UnitZ();        ///< unit principal axis of the smaller one; normal x axis_1
  double moment_1 = 0.0;              ///< I_1: second moment of area about axis_1, m^4
  double moment_2 = 0.0;              ///< I_2: second moment of area about axis_2, m^4
  double polar_moment = 0.0;          ///< J = I_1 + I_2, m^4
  double fibre_1 = 0.0;               ///< c_1: largest distance of the region from axis_1, m
  double fibre_2 = 0.0;               ///< c_2: largest distance of the region from axis_2, m
  double radius = 0.0;                ///< r_max: largest distance of the region from its centroid, m
  double length = 0.0;                ///< characteristic length: centroid a to plane + plane to centroid b, m
  /// Convex hull of the contact region, counter-clockwise, as (distance along axis_1, distance along
  /// axis_2) from the centroid, m. A linear stress field over the region peaks at one of these points,
  /// so the peak normal stress is exact for any section shape. Empty for bonds built by hand: the
  /// fibre distances are used then.
  std::vector<Vec2> section;
};

/// Nodes, bonds and per-node adjacency.
struct SupportGraph {
  std::vector<SupportNode> nodes;                ///< #fragments
  std::vector<Bond> bonds;                       ///< #bonds, sorted by (a, b)
  std::vector<std::vector<int>> node_bonds;      ///< #fragments lists of bond indices touching a node

  /// Number of nodes.
  [[nodiscard]] int node_count() const { return static_cast<int>(nodes.size()); }
  /// Number of bonds.
  [[nodiscard]] int bond_count() const { return static_cast<int>(bonds.size()); }
  /// The node across bond `bond` from `node`.
  [[nodiscard]] int other(int bond, int node) const {
    const Bond& e = bonds[static_cast<std::size_t>(bond)];
    return e.a == node ? e.b : e.a;
  }
};

/// How bonds are found. Defaults suit fragments of one fracture, in memory or re-read from OBJ.
struct SupportGraphSettings {
  double density = 2400.0;            ///< kg/m^3, > 0: node mass = density * volume
  double relative_tolerance = 1e-9;   ///< coplanarity tolerance as a share of the scene's bbox diagonal
  double min_relative_area = 1e-12;   ///< bonds smaller than this share of diagonal^2 are dropped
  /// Candidate faces: cut-tagged ones; a fragment with no cut-tagged face (e.g. read from OFF) offers
  /// all its faces. With `all_faces`, every face of every fragment is a candidate.
  bool all_faces = false;
};

/// Builds the graph of `fragments`. A fragment is anchored when its bounding box overlaps (closed
/// intervals) any of `anchors`: "an anchor region fixes every fragment that overlaps it"; for
/// non-convex fragments this is conservative. Errors for bad settings or non-finite geometry.
Result<SupportGraph> build_support_graph(std::span<const Fragment> fragments, std::span<const Aabb> anchors,
                                         const SupportGraphSettings& settings = {});

/// Builds the graph from bare meshes (mass properties computed here).
Result<SupportGraph> build_support_graph(std::span<const Mesh> meshes, std::span<const Aabb> anchors,
                                         const SupportGraphSettings& settings = {});

/// Fills `node_bonds` from `bonds` (for graphs built by hand in tests and benchmarks).
void index_bonds(SupportGraph& graph);

}  // namespace shatter
