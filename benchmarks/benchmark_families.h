#pragma once
/// The benchmark families registered at run time over a Registries: every plugin in it is benchmarked.

#include "algorithms/registry/registries.h"

namespace shatter {

/// fracture/<mesh>/<fracturer>/<n> for every fracturer of `registries` (and the slice/, voronoi/ and
/// self-intersection/ families); `registries` must outlive the benchmark run.
void register_fracture_benchmarks(const Registries& registries);

/// big-mesh/{read/off,read/obj,solid,metrics,fracture,command}: the fracture command's stages on
/// armadillo subdivided twice (832k triangles, generated on first use); `registries` must outlive the run.
void register_big_mesh_benchmarks(const Registries& registries);

/// attributes/<mesh>/<fracturer>/{geometry,attributes}/<n>: each fracturer on one solid with and
/// without attributes (attribute_benchmarks.cpp); `registries` must outlive the benchmark run.
void register_attribute_benchmarks(const Registries& registries);

/// colliders/<solid>/<fracturer>/{every-point,outer-points}/<n>: building the colliders of a
/// fracture's pieces with and without the points that cannot be hull corners (collider_benchmarks.cpp);
/// `registries` must outlive the benchmark run.
void register_collider_benchmarks(const Registries& registries);

/// physics/pile/<n>/<steps>: the physics steps of n plane-slice pieces of a block falling apart in
/// contact (physics_benchmarks.cpp); `registries` must outlive the benchmark run.
void register_physics_benchmarks(const Registries& registries);

/// evaluate_wall/<model> and cascade_wall/<model> for every stress model of `registries`, which must
/// outlive the benchmark run.
void register_stress_benchmarks(const Registries& registries);

/// boundary/...: the output checks beside the work they check, and the import in a child beside the
/// import in the process (boundary_benchmarks.cpp); `registries` must outlive the benchmark run.
void register_boundary_benchmarks(const Registries& registries);

}  // namespace shatter
