#pragma once
/// The representable range of an input solid: the coordinates every algorithm can measure and fracture
/// without overflow, underflow or a crash. A mesh outside it is refused before any algorithm runs, by
/// the harness where a mesh enters (make_solid) and by every fracturer at its entry
/// (check_fracture_params), so a library user calling a fracturer directly gets an Error too.
///
/// Design note: why these numbers. Mass properties grow as the extent L to the fifth power (volume
/// L^3, inertia L^5, products of coordinates up to degree 5 and 6 in the exact predicates); CGAL's
/// interval filters and lazy constructions multiply further (a plane through three points has a
/// degree-3 offset, the intersection of three such planes a degree-9 numerator). At |x| <= 1e9 m the
/// worst of these is about 1e81, far from the double's 1.8e308; at 1e80 m the filters overflow to
/// infinity and cgal-clip died with SIGFPE (SIGSEGV at 1e150), and at 1e100 m the volume itself
/// overflowed. 1e9 m is a million kilometres: no destructible scene comes near. The smallest extent
/// keeps the inertia (L^5) of the smallest piece far above the subnormal range: a 1e-6 m solid has an
/// inertia about 1e-30, and its fragments stay far above 1e-300; nothing a real-time destruction
/// benchmark fractures is smaller than a micrometre.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"

#include <string>

namespace shatter {

/// Largest absolute value of any coordinate of an input solid, m.
inline constexpr double kMaxCoordinate = 1e9;

/// Smallest extent of an input solid (the largest side of its bounding box), m.
inline constexpr double kMinExtent = 1e-6;

/// True when `p` is finite and every |coordinate| <= kMaxCoordinate.
bool within_coordinate_range(const Vec3& p);

/// Error unless every vertex of `mesh` is within the coordinate range; the message names `what`, the
/// first vertex outside and the range. What every fracturer checks at its entry (a fragment it is
/// asked to fracture again may be smaller than kMinExtent: the algorithms handle small pieces).
Status check_coordinate_range(const Mesh& mesh, const std::string& what);

/// check_coordinate_range, and an extent of at least kMinExtent: what an input solid must satisfy.
Status check_representable(const Mesh& mesh, const std::string& what);

}  // namespace shatter
