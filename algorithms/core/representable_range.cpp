#include "algorithms/core/representable_range.h"

#include <cmath>
#include <cstdio>

namespace shatter {
namespace {

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

}  // namespace

bool within_coordinate_range(const Vec3& p) {
  // Written so that NaN compares false and fails.
  return std::abs(p.x()) <= kMaxCoordinate && std::abs(p.y()) <= kMaxCoordinate && std::abs(p.z()) <= kMaxCoordinate;
}

Status check_coordinate_range(const Mesh& mesh, const std::string& what) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& p = mesh.vertices[v];
    if (!within_coordinate_range(p))
      return Error{what + ": vertex " + std::to_string(v) + " (" + number(p.x()) + ", " + number(p.y()) + ", " +
                   number(p.z()) + ") is outside the representable range: every coordinate must be finite and within +-" +
                   number(kMaxCoordinate) + " m"};
  }
  return {};
}

Status check_representable(const Mesh& mesh, const std::string& what) {
  if (Status s = check_coordinate_range(mesh, what); !s) return s;
  if (mesh.vertices.empty()) return {};
  Vec3 lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).maxCoeff();
  if (extent < kMinExtent)
    return Error{what + ": extent " + number(extent) + " m is below the representable range: the largest side of the bounding box must be at least " +
                 number(kMinExtent) + " m"};
  return {};
}

}  // namespace shatter
