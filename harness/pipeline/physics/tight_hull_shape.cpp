#include "harness/pipeline/physics/tight_hull_shape.h"

#include <algorithm>
#include <cmath>

namespace shatter {

void TightHullShape::getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const {
  const btMatrix3x3& r = t.getBasis();
  const btVector3& s = getLocalScaling();
  // World axis k in the hull's frame is row k of the rotation (times the scaling of the points).
  const btVector3 dx = r.getRow(0) * s, dy = r.getRow(1) * s, dz = r.getRow(2) * s;
  const btVector3* p = getUnscaledPoints();
  const int n = getNumPoints();
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
  double hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (int i = 0; i < n; ++i) {
    const double x = p[i].x(), y = p[i].y(), z = p[i].z();
    const double w[3] = {dx.x() * x + dx.y() * y + dx.z() * z, dy.x() * x + dy.y() * y + dy.z() * z,
                         dz.x() * x + dz.y() * y + dz.z() * z};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], w[k]);
      hi[k] = std::max(hi[k], w[k]);
    }
  }
  const double margin = getMargin();
  for (int k = 0; k < 3; ++k) {
    const double o = t.getOrigin()[k];
    // Bullet moves the points in btScalar: a few units of its precision at these coordinates.
    const double slack = margin + 1e-6 + 1e-6 * (std::abs(o) + std::max(std::abs(lo[k]), std::abs(hi[k])));
    aabb_min[k] = static_cast<btScalar>(o + lo[k] - slack);
    aabb_max[k] = static_cast<btScalar>(o + hi[k] + slack);
  }
}

void TightHullShape::getBoundingSphere(btVector3& center, btScalar& radius) const {
  btTransform identity;
  identity.setIdentity();
  btVector3 aabb_min, aabb_max;
  btConvexHullShape::getAabb(identity, aabb_min, aabb_max);
  radius = (aabb_max - aabb_min).length() * btScalar(0.5);
  center = (aabb_min + aabb_max) * btScalar(0.5);
}

}  // namespace shatter
