#pragma once
/// Closed, outward-oriented primitive solids, tagged `FaceTag::surface`. Curved primitives are
/// polyhedral approximations; their exact (polyhedral) volume comes from mass_properties.

#include "algorithms/core/mesh.h"

namespace shatter {

/// Axis-aligned box with the given edge lengths (m) centred at `center`; 12 triangles.
Mesh make_box(const Vec3& size, const Vec3& center = Vec3::Zero());

/// UV sphere of `radius` (m), `segments` around the axis (>= 3) and `rings` from pole to pole (>= 2).
Mesh make_sphere(double radius, int segments = 32, int rings = 16, const Vec3& center = Vec3::Zero());

/// Cylinder along z of `radius` and `height` (m), centred at `center`, `segments` >= 3 around.
Mesh make_cylinder(double radius, double height, int segments = 32, const Vec3& center = Vec3::Zero());

/// Thick tube (a cylinder with a coaxial hole) along z; inner_radius < outer_radius.
Mesh make_tube(double inner_radius, double outer_radius, double height, int segments = 32,
               const Vec3& center = Vec3::Zero());

/// Torus around the z axis: `major_radius` to the tube centre, `minor_radius` of the tube (m).
Mesh make_torus(double major_radius, double minor_radius, int major_segments = 32, int minor_segments = 16,
                const Vec3& center = Vec3::Zero());

}  // namespace shatter
