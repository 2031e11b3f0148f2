#include "harness/pipeline/physics/physics_world.h"
#include "harness/pipeline/physics/collider_points.h"
#include "harness/pipeline/physics/hull_pair_collision.h"
#include "harness/pipeline/physics/narrow_phase_dispatcher.h"
#include "harness/pipeline/physics/presized_pools.h"
#include "harness/pipeline/physics/tight_hull_shape.h"

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionShapes/btShapeHull.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace shatter {
namespace {

/// Always-on precondition check (not compiled out in release builds): a broken caller aborts loudly.
void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "shatter::PhysicsWorld: precondition failed: %s\n", what);
    std::abort();
  }
}

btVector3 to_bt(const Vec3& v) {
  return {static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z())};
}

Vec3 from_bt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

btMatrix3x3 to_bt_matrix(const Eigen::Matrix3d& m) {
  return {static_cast<btScalar>(m(0, 0)), static_cast<btScalar>(m(0, 1)), static_cast<btScalar>(m(0, 2)),
          static_cast<btScalar>(m(1, 0)), static_cast<btScalar>(m(1, 1)), static_cast<btScalar>(m(1, 2)),
          static_cast<btScalar>(m(2, 0)), static_cast<btScalar>(m(2, 1)), static_cast<btScalar>(m(2, 2))};
}

Eigen::Matrix3d from_bt(const btMatrix3x3& m) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m[i][j];
  return r;
}

/// Mass properties of one rigid body, per unit density (m^3, m, m^5).
struct BodyMass {
  double volume = 0.0;
  Vec3 centroid = Vec3::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about `centroid`
};

void require_valid(const Fragment& f) {
  require(f.mesh.vertices.size() >= 4, "fragment has fewer than 4 vertices");
  require(std::isfinite(f.mass.volume) && f.mass.volume > 0.0, "fragment volume must be finite and > 0");
  require(f.mass.centroid.allFinite() && f.mass.inertia.allFinite(), "fragment mass properties not finite");
  for (const Vec3& p : f.mesh.vertices) require(p.allFinite(), "fragment vertex not finite");
}

/// Combined mass properties of `fragments` (parallel-axis theorem about the common centroid).
BodyMass combine(std::span<const Fragment> fragments) {
  BodyMass total;
  for (const Fragment& f : fragments) {
    total.volume += f.mass.volume;
    total.centroid += f.mass.volume * f.mass.centroid;
  }
  total.centroid /= total.volume;
  for (const Fragment& f : fragments) {
    const Vec3 d = f.mass.centroid - total.centroid;
    total.inertia += f.mass.inertia +
                     f.mass.volume * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return total;
}

/// The world's margin in Bullet's bounding-volume tree for the length of a call that moves boxes in the
/// tree (a step, a rescale); Bullet's own value back afterwards (it is one process-wide variable).
class TreeMarginScope {
 public:
  explicit TreeMarginScope(double margin) : saved_(gDbvtMargin) { gDbvtMargin = static_cast<btScalar>(margin); }
  ~TreeMarginScope() { gDbvtMargin = saved_; }
  TreeMarginScope(const TreeMarginScope&) = delete;
  TreeMarginScope& operator=(const TreeMarginScope&) = delete;

 private:
  btScalar saved_;
};

}  // namespace

Status validate_physics_settings(const PhysicsSettings& s) {
  if (!s.gravity.allFinite()) return Error{"physics.gravity: must be finite"};
  if (!std::isfinite(s.fixed_step) || s.fixed_step <= 0.0)
    return Error{"physics.fixed_step: must be finite and > 0 s, got " + std::to_string(s.fixed_step)};
  if (!std::isfinite(s.ground_z)) return Error{"physics.ground_z: must be finite"};
  if (s.max_hull_vertices < 0) return Error{"physics.max_hull_vertices: must be >= 0 (0 = no cap)"};
  if (s.hull_optimize_above < 0) return Error{"physics.hull_optimize_above: must be >= 0"};
  if (s.hull_vertex_budget != 0 && s.hull_vertex_budget < 4)
    return Error{"physics.hull_vertex_budget: must be 0 (none) or >= 4, got " + std::to_string(s.hull_vertex_budget)};
  if (s.contact_pool_size < 1)
    return Error{"physics.contact_pool_size: must be >= 1, got " + std::to_string(s.contact_pool_size)};
  if (!std::isfinite(s.collision_margin) || s.collision_margin < 0.0)
    return Error{"physics.collision_margin: must be finite and >= 0 m"};
  if (!std::isfinite(s.broadphase_margin) || s.broadphase_margin < 0.0)
    return Error{"physics.broadphase_margin: must be finite and >= 0 m"};
  if (!std::isfinite(s.friction) || s.friction < 0.0) return Error{"physics.friction: must be >= 0"};
  if (!std::isfinite(s.restitution) || s.restitution < 0.0 || s.restitution > 1.0)
    return Error{"physics.restitution: must be in [0, 1]"};
  return {};
}

/// One body: Bullet objects plus the rotation of its principal frame in mesh coordinates.
struct Body {
  std::vector<std::unique_ptr<btCollisionShape>> children;  ///< hulls of a compound, else empty
  std::unique_ptr<btCollisionShape> shape;                   ///< the body's collision shape
  std::unique_ptr<btRigidBody> rigid;
  Eigen::Matrix3d principal = Eigen::Matrix3d::Identity();   ///< principal axes (columns), mesh frame
  Vec3 mesh_centroid = Vec3::Zero();                         ///< centroid in mesh coordinates, m
  double scale = 1.0;                                        ///< the collider's scale (set_scale)
  bool in_world = true;                                      ///< added to the dynamics world
};

/// Bullet's pools of contact manifolds and collision algorithms, sized by `s.contact_pool_size`.
btDefaultCollisionConstructionInfo pool_info(const PhysicsSettings& s) {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = s.contact_pool_size;
  info.m_defaultMaxCollisionAlgorithmPoolSize = s.contact_pool_size;
  return info;
}

struct PhysicsWorld::Impl {
  PhysicsSettings settings;
  // Declaration order = construction order; members are destroyed in reverse (world first).
  btDefaultCollisionConfiguration configuration{pool_info(settings)};
  HullPairCollision hull_pairs;  ///< outlives the dispatcher that points to it
  NarrowPhaseDispatcher dispatcher{&configuration};
  PresizedPairCache pairs{settings.contact_pool_size};  ///< outlives the broadphase that uses it
  btDbvtBroadphase broadphase{&pairs};
  PresizedSolver solver{settings.contact_pool_size};
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::unique_ptr<btCollisionShape> ground_shape;
  std::unique_ptr<btRigidBody> ground;
  std::vector<std::unique_ptr<Body>> bodies;  ///< by id; null once removed
  int live = 0;
  long steps = 0;

  explicit Impl(const PhysicsSettings& s) : settings(s) {
    if (s.keep_separating_axes) hull_pairs.register_with(dispatcher);
    world.setGravity(to_bt(s.gravity));
    if (s.ground) {
      ground_shape = std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), static_cast<btScalar>(s.ground_z));
      btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, ground_shape.get());
      info.m_friction = static_cast<btScalar>(s.friction);
      info.m_restitution = static_cast<btScalar>(s.restitution);
      ground = std::make_unique<btRigidBody>(info);
      world.addRigidBody(ground.get());
    }
  }

  ~Impl() {
    for (auto& b : bodies)
      if (b) world.removeRigidBody(b->rigid.get());
    if (ground) world.removeRigidBody(ground.get());
  }

  const Body& body(int id) const {
    require(id >= 0 && id < static_cast<int>(bodies.size()) && bodies[id], "unknown or removed body id");
    return *bodies[id];
  }

  /// The `chosen` vertices of `fragment`, in that order, moved inward so that the hull plus the
  /// collision margin is the fragment again: each vertex moves by the d with n . d = -margin for every
  /// distinct plane n of its faces (`planes`; least squares, minimum norm: exact for a corner of three
  /// planes, on an edge or in a face it moves along the shared normals only). Each move is capped at
  /// half the vertex's distance from the centroid, so a needle corner cannot be pushed through the
  /// fragment.
  std::vector<Vec3> inset_points(const Fragment& fragment, const VertexPlanes& planes,
                                 std::span<const std::int32_t> chosen) const {
    const double margin = settings.collision_margin;
    std::vector<Vec3> points;
    points.reserve(chosen.size());
    for (const std::int32_t v : chosen) {
      Vec3 p = fragment.mesh.vertices[static_cast<std::size_t>(v)];
      const std::span<const Vec3> normals = planes.normals_of(static_cast<std::size_t>(v));
      if (margin > 0.0 && !normals.empty()) {
        // Normal equations (sum n n^T) d = -margin sum n, solved by the pseudo-inverse (minimum norm).
        Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
        Vec3 rhs = Vec3::Zero();
        for (const Vec3& n : normals) {
          a += n * n.transpose();
          rhs -= margin * n;
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
        eig.computeDirect(a);
        Vec3 d = Vec3::Zero();
        for (int k = 0; k < 3; ++k) {
          const double lambda = eig.eigenvalues()[k];
          if (lambda > 1e-9 * eig.eigenvalues()[2]) {
            const Vec3 e = eig.eigenvectors().col(k);
            d += (e.dot(rhs) / lambda) * e;
          }
        }
        const double cap = 0.5 * (p - fragment.mass.centroid).norm();
        if (d.allFinite()) {
          if (d.norm() > cap) d *= cap / d.norm();
          p += d;
        }
      }
      points.push_back(p);
    }
    return points;
  }

  /// An empty hull (or one of `count` points), with exact world boxes when the settings ask for them.
  std::unique_ptr<btConvexHullShape> new_hull(const btScalar* points, int count) const {
    if (settings.tight_bounds) return std::make_unique<TightHullShape>(points, count);
    return std::make_unique<btConvexHullShape>(points, count);
  }

  /// A convex hull of `fragment`'s vertices, inset by the collision margin (inset_points) so that
  /// neighbouring fragments that share a face start touching instead of interpenetrating, expressed in
  /// the body's principal frame (`centroid`, `axes`).
  std::unique_ptr<btCollisionShape> make_hull(const Fragment& fragment, const Vec3& centroid,
                                              const Eigen::Matrix3d& axes) const {
    const Mesh& mesh = fragment.mesh;
    const VertexPlanes planes = vertex_planes(mesh);
    const std::vector<std::int32_t> chosen =
        collider_vertex_indices(mesh, planes, settings.drop_inner_points, settings.hull_vertex_budget);
    const std::vector<Vec3> points = inset_points(fragment, planes, chosen);
    std::unique_ptr<btConvexHullShape> hull = new_hull(nullptr, 0);
    for (const Vec3& p : points) hull->addPoint(to_bt(axes.transpose() * (p - centroid)), false);
    hull->recalcLocalAabb();
    // Keep only the hull's own vertices when that pays: Bullet's support mapping scans every point, so
    // a few interior points cost less than computing the hull (about 50 us for a 30-point fragment).
    if (static_cast<int>(points.size()) > settings.hull_optimize_above) hull->optimizeConvexHull();
    const int cap = settings.max_hull_vertices;
    if (cap > 0 && hull->getNumPoints() > cap) {
      btShapeHull reduced(hull.get());
      reduced.buildHull(hull->getMargin());
      hull = new_hull(reinterpret_cast<const btScalar*>(reduced.getVertexPointer()), reduced.numVertices());
    }
    hull->setMargin(static_cast<btScalar>(settings.collision_margin));
    return hull;
  }

  /// A body made of `fragments` with their combined mass properties at `density`, before Bullet's
  /// rigid body exists: its hulls, mass and placement. Reads only `settings`, so bodies of different
  /// fragments can be planned on different threads.
  struct BodyPlan {
    std::unique_ptr<Body> body;
    double mass = 0.0;
    btVector3 inertia{0, 0, 0};
    btTransform start;
  };

  BodyPlan plan(std::span<const Fragment> fragments, double density, bool is_static) const {
    require(!fragments.empty(), "a body needs at least one fragment");
    require(std::isfinite(density) && density > 0.0, "density must be finite and > 0 kg/m^3");
    for (const Fragment& f : fragments) require_valid(f);
    const BodyMass m = combine(fragments);

    BodyPlan out;
    out.body = std::make_unique<Body>();
    Body& b = *out.body;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(density * m.inertia);
    b.principal = eig.eigenvectors();
    if (b.principal.determinant() < 0.0) b.principal.col(2) *= -1.0;  // a proper rotation
    b.mesh_centroid = m.centroid;
    const Vec3 moments = eig.eigenvalues();  // ascending, kg m^2

    if (fragments.size() == 1) {
      b.shape = make_hull(fragments[0], m.centroid, b.principal);
    } else {
      auto compound = std::make_unique<btCompoundShape>();
      btTransform identity;
      identity.setIdentity();
      for (const Fragment& f : fragments) {
        b.children.push_back(make_hull(f, m.centroid, b.principal));
        compound->addChildShape(identity, b.children.back().get());
      }
      b.shape = std::move(compound);
    }
    out.mass = is_static ? 0.0 : density * m.volume;
    out.inertia = is_static ? btVector3(0, 0, 0) : to_bt(moments);
    out.start = btTransform(to_bt_matrix(b.principal), to_bt(m.centroid));
    return out;
  }

  /// Gives a planned body its rigid body (Bullet numbers rigid bodies from a global counter: one thread
  /// only) and its id, in the world or only prepared.
  int store(BodyPlan&& planned, bool in_world) {
    std::unique_ptr<Body> b = std::move(planned.body);
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(planned.mass), nullptr, b->shape.get(),
                                                  planned.inertia);
    info.m_startWorldTransform = planned.start;
    info.m_friction = static_cast<btScalar>(settings.friction);
    info.m_restitution = static_cast<btScalar>(settings.restitution);
    b->rigid = std::make_unique<btRigidBody>(info);
    b->rigid->setUserIndex(static_cast<int>(bodies.size()));  // the id, for touching_pairs()
    if (!settings.allow_sleeping) b->rigid->setActivationState(DISABLE_DEACTIVATION);
    b->in_world = in_world;
    if (in_world) {
      world.addRigidBody(b->rigid.get());
      ++live;
    }
    bodies.push_back(std::move(b));
    return static_cast<int>(bodies.size()) - 1;
  }

  /// Adds a body made of `fragments` with their combined mass properties at `density`.
  int add(std::span<const Fragment> fragments, double density, bool is_static, bool in_world = true) {
    return store(plan(fragments, density, is_static), in_world);
  }
};

Result<PhysicsWorld> PhysicsWorld::create(const PhysicsSettings& settings) {
  if (Status s = validate_physics_settings(settings); !s.ok()) return s.error();
  return PhysicsWorld(settings);
}

PhysicsWorld::PhysicsWorld(const PhysicsSettings& settings) {
  const Status s = validate_physics_settings(settings);
  require(s.ok(), "invalid PhysicsSettings (use PhysicsWorld::create for an error value)");
  impl_ = std::make_unique<Impl>(settings);
}

PhysicsWorld::~PhysicsWorld() = default;
PhysicsWorld::PhysicsWorld(PhysicsWorld&&) noexcept = default;
PhysicsWorld& PhysicsWorld::operator=(PhysicsWorld&&) noexcept = default;

int PhysicsWorld::add_fragment(const Fragment& fragment, double density, bool is_static) {
  return impl_->add(std::span<const Fragment>(&fragment, 1), density, is_static);
}

int PhysicsWorld::add_cluster(std::span<const Fragment> fragments, double density, bool is_static) {
  return impl_->add(fragments, density, is_static);
}

int PhysicsWorld::prepare_fragment(const Fragment& fragment, double density) {
  return impl_->add(std::span<const Fragment>(&fragment, 1), density, false, /*in_world=*/false);
}

std::vector<int> PhysicsWorld::prepare_fragments(std::span<const Fragment* const> fragments, double density,
                                                 Workers& workers) {
  std::vector<Impl::BodyPlan> plans(fragments.size());
  workers.for_each(fragments.size(), [&](std::size_t i) {
    plans[i] = impl_->plan(std::span<const Fragment>(fragments[i], 1), density, false);
  });
  std::vector<int> ids;
  ids.reserve(plans.size());
  for (Impl::BodyPlan& planned : plans) ids.push_back(impl_->store(std::move(planned), /*in_world=*/false));
  return ids;
}

int PhysicsWorld::prepare_cluster(std::span<const Fragment> fragments, double density) {
  return impl_->add(fragments, density, false, /*in_world=*/false);
}

void PhysicsWorld::insert(int body) {
  Body& b = const_cast<Body&>(impl_->body(body));
  require(!b.in_world, "the body is already in the world");
  impl_->world.addRigidBody(b.rigid.get());
  b.in_world = true;
  ++impl_->live;
}

bool PhysicsWorld::in_world(int body) const { return impl_->body(body).in_world; }

void PhysicsWorld::set_scale(int body, double scale) {
  require(std::isfinite(scale) && scale > 0.0, "scale must be finite and > 0");
  Body& b = const_cast<Body&>(impl_->body(body));
  b.scale = scale;
  b.shape->setLocalScaling(btVector3(static_cast<btScalar>(scale), static_cast<btScalar>(scale), static_cast<btScalar>(scale)));
  if (b.in_world) {
    const TreeMarginScope margin(impl_->settings.broadphase_margin);
    impl_->world.updateSingleAabb(b.rigid.get());
  }
}

void PhysicsWorld::remove(int body) {
  impl_->body(body);  // checks the id
  if (impl_->bodies[body]->in_world) {
    impl_->world.removeRigidBody(impl_->bodies[body]->rigid.get());
    --impl_->live;
  }
  impl_->bodies[body].reset();
}

void PhysicsWorld::apply_impulse(int body, const Vec3& impulse_Ns, const Vec3& world_point) {
  require(impulse_Ns.allFinite() && world_point.allFinite(), "impulse and point must be finite");
  btRigidBody& rigid = *impl_->body(body).rigid;
  if (rigid.isStaticObject()) return;  // infinite mass: no effect
  rigid.activate(true);
  rigid.applyImpulse(to_bt(impulse_Ns), to_bt(world_point - position(body)));
}

void PhysicsWorld::step() {
  const auto dt = static_cast<btScalar>(impl_->settings.fixed_step);
  const TreeMarginScope margin(impl_->settings.broadphase_margin);
  impl_->world.stepSimulation(dt, 0);  // maxSubSteps = 0: exactly one step of dt, no interpolation
  ++impl_->steps;
}

Vec3 PhysicsWorld::position(int body) const {
  return from_bt(impl_->body(body).rigid->getCenterOfMassPosition());
}

Eigen::Matrix3d PhysicsWorld::rotation(int body) const {
  const Body& b = impl_->body(body);
  return from_bt(b.rigid->getCenterOfMassTransform().getBasis()) * b.principal.transpose();
}

Vec3 PhysicsWorld::mesh_centroid(int body) const { return impl_->body(body).mesh_centroid; }

double PhysicsWorld::scale(int body) const { return impl_->body(body).scale; }

std::vector<Vec3> PhysicsWorld::collider_points(int body) const {
  const Body& b = impl_->body(body);
  const btTransform& to_world = b.rigid->getCenterOfMassTransform();
  std::vector<Vec3> out;
  const auto add = [&](const btCollisionShape& shape) {
    const auto& hull = static_cast<const btConvexHullShape&>(shape);
    for (int i = 0; i < hull.getNumPoints(); ++i) out.push_back(from_bt(to_world(hull.getScaledPoint(i))));
  };
  if (b.children.empty()) {
    add(*b.shape);
  } else {
    for (const auto& child : b.children) add(*child);
  }
  return out;
}

Vec3 PhysicsWorld::linear_velocity(int body) const {
  return from_bt(impl_->body(body).rigid->getLinearVelocity());
}

Vec3 PhysicsWorld::angular_velocity(int body) const {
  return from_bt(impl_->body(body).rigid->getAngularVelocity());
}

double PhysicsWorld::mass(int body) const {
  const btScalar inv = impl_->body(body).rigid->getInvMass();
  return inv == 0 ? 0.0 : 1.0 / static_cast<double>(inv);
}

Vec3 PhysicsWorld::principal_inertia(int body) const {
  const Vec3 inv = from_bt(impl_->body(body).rigid->getInvInertiaDiagLocal());
  return inv.unaryExpr([](double x) { return x == 0.0 ? 0.0 : 1.0 / x; });
}

bool PhysicsWorld::contains(int body) const {
  return body >= 0 && body < static_cast<int>(impl_->bodies.size()) && impl_->bodies[body] != nullptr;
}

int PhysicsWorld::body_count() const { return impl_->live; }

int PhysicsWorld::id_bound() const { return static_cast<int>(impl_->bodies.size()); }

HullPairCounts PhysicsWorld::hull_pair_counts() const { return impl_->hull_pairs.counts(); }

void PhysicsWorld::set_workers(Workers* workers) { impl_->dispatcher.set_workers(workers); }

std::vector<TouchingPair> PhysicsWorld::touching_pairs() const {
  std::vector<TouchingPair> out;
  const btCollisionDispatcher& d = impl_->dispatcher;
  for (int i = 0; i < d.getNumManifolds(); ++i) {
    const btPersistentManifold* m = d.getManifoldByIndexInternal(i);
    if (m->getNumContacts() == 0) continue;
    const bool ground0 = m->getBody0() == impl_->ground.get(), ground1 = m->getBody1() == impl_->ground.get();
    TouchingPair p{ground0 ? -1 : m->getBody0()->getUserIndex(), ground1 ? -1 : m->getBody1()->getUserIndex(),
                   m->getNumContacts()};
    if (p.first > p.second) std::swap(p.first, p.second);
    out.push_back(p);
  }
  std::sort(out.begin(), out.end(), [](const TouchingPair& a, const TouchingPair& b) {
    return std::tie(a.first, a.second, a.points) < std::tie(b.first, b.second, b.points);
  });
  return out;
}

int PhysicsWorld::overlapping_pairs() const {
  return impl_->broadphase.getOverlappingPairCache()->getNumOverlappingPairs();
}

long PhysicsWorld::step_count() const { return impl_->steps; }

const PhysicsSettings& PhysicsWorld::settings() const { return impl_->settings; }

}  // namespace shatter
