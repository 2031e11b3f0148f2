#pragma once
/// A thin rigid-body world over Bullet for the frame pipeline (DESIGN.md section 3: colliders and
/// physics steps).
///
/// Design note. Each body is one fragment (or one cluster of fragments) as a convex hull of its mesh
/// vertices, with the *exact* mass properties of the closed mesh: mass = density * volume, and the
/// inertia tensor about the centroid diagonalised into principal moments. Bullet wants a diagonal
/// local inertia, so the body's local frame is the principal frame: origin at the centroid, axes the
/// eigenvectors of the inertia tensor; the hull vertices are expressed in that frame. Callers never
/// see the principal frame: `position` is the world centroid and `rotation` maps the fragment's
/// original mesh coordinates to the world, `x_world = rotation * (x_mesh - centroid_0) + position`, so
/// a body added and never moved has the identity rotation.
///
/// Bullet (Debian's 3.24) is single precision; everything here is double and converted at the
/// boundary. Bullet headers stay in physics_world.cpp (pimpl), so including this header is cheap.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "harness/pipeline/physics/hull_pair_collision.h"
#include "harness/pipeline/workers.h"

#include <Eigen/Core>

#include <memory>
#include <span>
#include <vector>

namespace shatter {

/// Settings of a PhysicsWorld; plain data with documented defaults.
struct PhysicsSettings {
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  ///< m/s^2, world
  double fixed_step = 1.0 / 60.0;        ///< s, the length of one step() (> 0)
  bool ground = false;                   ///< a static ground plane z = ground_z, normal +z, when true
  double ground_z = 0.0;                 ///< m, height of the ground plane
  /// Hull reduction threshold: a fragment whose convex hull has more vertices than this gets a reduced
  /// hull (Bullet's btShapeHull: the hull's support points in 42 fixed directions, so about 42
  /// vertices; a trigger, not an exact cap); 0 = never reduce. Mass properties always come from the
  /// full mesh, only the collider is reduced.
  int max_hull_vertices = 0;
  /// At most this many points per collider (collider_points.h: the piece's points extreme along a
  /// fixed spread of directions, so the collider lies inside the piece); 0 = every hull point. Mass
  /// properties always come from the full mesh. 0 or >= 4.
  int hull_vertex_budget = 0;
  /// A fragment with more vertices than this gets its convex hull computed (interior points dropped);
  /// below, every vertex is kept as a hull point (same shape, Bullet's support mapping ignores interior
  /// points; computing the hull would cost more than it saves). >= 0.
  int hull_optimize_above = 64;
  /// m, Bullet's collision margin around each hull (Bullet's default is 0.04). Each hull vertex is
  /// first moved inward so that every face plane through it moves in by the margin: hull plus margin is
  /// the fragment again, and fragments that share a face start touching, not interpenetrating (which
  /// would cost deep-penetration solves and push them apart). >= 0.
  double collision_margin = 0.01;
  double friction = 0.5;                 ///< Coulomb friction coefficient of every body and the ground
  double restitution = 0.0;              ///< coefficient of restitution of every body and the ground
  bool allow_sleeping = true;            ///< let Bullet deactivate bodies at rest (faster, still exact)
  /// Contact manifolds (and as many collision algorithms) Bullet allocates when the world is made;
  /// a pair beyond them is allocated (and zeroed) in the step that finds it. One per overlapping pair
  /// of bounding boxes, so a scene's peak of pairs sized here moves that cost from the event's step
  /// into the world's creation. The broadphase's pair cache and the solver's contact and friction
  /// constraint arrays are made at this size too (presized_pools.h). Changes no result. >= 1
  /// (Bullet's default 4096).
  int contact_pool_size = 4096;
  /// Pairs of hulls keep the axis that last proved them apart and skip GJK while it still does
  /// (hull_pair_collision.h). Changes no result: the same contacts, bit for bit.
  bool keep_separating_axes = true;
  /// Each hull's bounding box is the exact world box of its points (tight_hull_shape.h), not the turned
  /// box of its local one: fewer broadphase pairs, the same contacts. The solver meets them in another
  /// order, so trajectories differ as they do when Bullet gets the same bodies in another order.
  bool tight_bounds = true;
  /// m, how far a moving body's box in Bullet's bounding-volume tree is grown beyond its own (Bullet's
  /// `gDbvtMargin`, 0.05 m): a move that stays inside the grown box does not update the tree, and two
  /// bodies are a pair, tested every step, while their grown boxes overlap. Pieces of a decimetre in a
  /// pile with Bullet's 0.05 m are pairs with dozens of neighbours they do not touch (the wall's pile of
  /// 787 pieces: 29,000 pairs). Changes no contact: the grown box holds the body's own box, which holds
  /// the hull, its margin and the contact threshold, at any margin. The pairs, and with them the islands
  /// and the solver's order, change: trajectories differ as with another body order
  /// (tests/.../broadphase_margin_tests.cpp). Bullet keeps it in one process-wide variable, which a
  /// step sets and restores: steps of two worlds must not run at the same time. >= 0.
  double broadphase_margin = 0.01;
  /// A collider keeps only the piece's points that can be corners of its hull (outer_points.h): points
  /// on the straight run of an edge or inside a flat face are dropped before the margin inset, so
  /// there are fewer points to inset, reduce and scan. Before the inset the hull is the same to
  /// round-off; after it, the collider loses the bulges where such a point near a corner, moved in
  /// along its own faces only, landed beyond the corner's inset (and out of the piece with the margin).
  /// Trajectories differ as with another body order (tests/.../outer_points_tests.cpp).
  bool drop_inner_points = true;
};

/// Two bodies in contact after a step, by id (the ground plane is -1), first < second.
struct TouchingPair {
  int first = 0;
  int second = 0;
  int points = 0;  ///< contact points between them
  friend bool operator==(const TouchingPair&, const TouchingPair&) = default;
};

/// Checks `s`: finite values, fixed_step > 0, max_hull_vertices >= 0, hull_optimize_above >= 0,
/// hull_vertex_budget 0 or >= 4, collision_margin >= 0, broadphase_margin >= 0, friction >= 0,
/// restitution in [0, 1], contact_pool_size >= 1. The error names the field ("physics.fixed_step: ...").
Status validate_physics_settings(const PhysicsSettings& s);

/// A Bullet dynamics world with fragment bodies addressed by integer ids (never reused).
class PhysicsWorld {
 public:
  /// A world from checked settings; an error when validate_physics_settings fails.
  static Result<PhysicsWorld> create(const PhysicsSettings& settings);
  /// A world from settings that must be valid (programmer error otherwise: aborts).
  explicit PhysicsWorld(const PhysicsSettings& settings = {});
  ~PhysicsWorld();
  PhysicsWorld(PhysicsWorld&&) noexcept;
  PhysicsWorld& operator=(PhysicsWorld&&) noexcept;
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// Adds `fragment` (closed, volume > 0, finite) at rest where its mesh is, of `density` (kg/m^3,
  /// > 0); a static body never moves and has infinite mass. Returns the body id (>= 0).
  int add_fragment(const Fragment& fragment, double density, bool is_static = false);
  /// Adds `fragments` as one rigid body (a compound of their hulls) with the combined exact mass
  /// properties (parallel-axis theorem about the common centroid). Non-empty. Returns the body id.
  int add_cluster(std::span<const Fragment> fragments, double density, bool is_static = false);
  /// Makes a dynamic body of `fragment` (as add_fragment) without putting it in the world: the
  /// collider's cost can be paid before the body takes part (an amortized event). insert() adds it.
  int prepare_fragment(const Fragment& fragment, double density);
  /// Makes a dynamic body of each of `fragments` as prepare_fragment does, their hulls built on
  /// `workers`; the ids in the order of `fragments`, the same bodies on any number of threads.
  std::vector<int> prepare_fragments(std::span<const Fragment* const> fragments, double density, Workers& workers);
  /// Makes a dynamic compound of `fragments` (as add_cluster) without putting it in the world.
  int prepare_cluster(std::span<const Fragment> fragments, double density);
  /// Puts a prepared body into the world (once).
  void insert(int body);
  /// True when `body` (a live id) takes part in the world (not only prepared).
  [[nodiscard]] bool in_world(int body) const;
  /// Scales the body's collider uniformly about its centroid by `scale` (> 0; 1 = as made); the mass
  /// properties stay (a fading piece shrinks visually and in contact, not in inertia).
  void set_scale(int body, double scale);
  /// Removes body `body` (in the world or only prepared); its id becomes invalid and is never reused.
  void remove(int body);

  /// Applies `impulse_Ns` (N s, world) at `world_point` (m, world) to a dynamic body, waking it.
  void apply_impulse(int body, const Vec3& impulse_Ns, const Vec3& world_point);
  /// Advances the world by one fixed step (settings().fixed_step seconds, no sub-stepping).
  void step();
  /// Runs the narrow phase of the next steps on `workers` (none: on the calling thread). The same
  /// contacts and trajectories, bit for bit, on any number of threads (narrow_phase_dispatcher.h).
  /// `workers` must outlive the world or be replaced first.
  void set_workers(Workers* workers);

  /// World position of the body's centroid, m.
  [[nodiscard]] Vec3 position(int body) const;
  /// Rotation from the fragment's original mesh coordinates to the world (identity until it turns).
  [[nodiscard]] Eigen::Matrix3d rotation(int body) const;
  /// The body's centroid in the fragments' original mesh coordinates, m (where it was made):
  /// `x_world = rotation(body) * (x_mesh - mesh_centroid(body)) + position(body)`.
  [[nodiscard]] Vec3 mesh_centroid(int body) const;
  /// The collider's scale set by set_scale (1 as made).
  [[nodiscard]] double scale(int body) const;
  /// Velocity of the body's centroid, m/s, world.
  [[nodiscard]] Vec3 linear_velocity(int body) const;
  /// Angular velocity, rad/s, world.
  [[nodiscard]] Vec3 angular_velocity(int body) const;
  /// The points of the body's collider (of each hull of a compound), world coordinates, m: the hull
  /// the margin is added around.
  [[nodiscard]] std::vector<Vec3> collider_points(int body) const;
  /// Mass as Bullet holds it, kg (0 for a static body).
  [[nodiscard]] double mass(int body) const;
  /// Principal moments of inertia as Bullet holds them, kg m^2, ascending (0 for a static body).
  [[nodiscard]] Vec3 principal_inertia(int body) const;
  /// True when `body` is a live id.
  [[nodiscard]] bool contains(int body) const;
  /// Number of bodies in the world (prepared ones and the ground plane are not counted).
  [[nodiscard]] int body_count() const;
  /// Ids given so far: every id ever returned is below it (ids count up from 0, removed ones included).
  [[nodiscard]] int id_bound() const;
  /// Pairs of bodies whose bounding boxes overlap (Bullet's broadphase pairs, each with a contact
  /// manifold: PhysicsSettings::contact_pool_size), as of the last step.
  [[nodiscard]] int overlapping_pairs() const;
  /// The hull pair tests of all steps so far and how many a kept separating axis answered (zeros
  /// when settings().keep_separating_axes is off).
  [[nodiscard]] HullPairCounts hull_pair_counts() const;
  /// The pairs of bodies with contact points after the last step, sorted.
  [[nodiscard]] std::vector<TouchingPair> touching_pairs() const;
  /// Number of step() calls so far.
  [[nodiscard]] long step_count() const;
  /// The settings the world was made with.
  [[nodiscard]] const PhysicsSettings& settings() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shatter
