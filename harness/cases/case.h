#pragma once
/// A benchmark case: the solid, its material, supports, pre-fracture, impacts and run settings, as read
/// from a case file (DESIGN.md section 9; every key is documented in cases/README.md).
///
/// Design note: a Case is plain data with the defaults of the case-file contract, checked once by the
/// loader (ranges, finiteness, required keys, unknown keys). Algorithm names (fracturers, stress
/// models) are kept as strings and NOT checked here: the loader stays independent of the registries,
/// and the caller that creates the algorithms reports an unknown name with the list of known ones.
/// The mesh is only described (MeshSpec); case_mesh.h builds and validates it.

#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/core/plugin_settings.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/core/material.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace shatter {

/// `mesh.box`: an axis-aligned box.
struct BoxSpec {
  Vec3 size = Vec3::Ones();          ///< edge lengths, m, each > 0
  Vec3 center = Vec3::Zero();        ///< m
};

/// `mesh.sphere`: a UV sphere.
struct SphereSpec {
  double radius = 1.0;               ///< m, > 0
  Vec3 center = Vec3::Zero();        ///< m
  int segments = 32;                 ///< around the axis, >= 3
  int rings = 16;                    ///< pole to pole, >= 2
};

/// `mesh.cylinder`: a cylinder along z.
struct CylinderSpec {
  double radius = 1.0;               ///< m, > 0
  double height = 1.0;               ///< m, > 0
  Vec3 center = Vec3::Zero();        ///< m
  int segments = 32;                 ///< around the axis, >= 3
};

/// `mesh.torus`: a torus around the z axis.
struct TorusSpec {
  double major_radius = 1.0;         ///< axis to tube centre, m, > minor_radius
  double minor_radius = 0.25;        ///< tube radius, m, > 0
  Vec3 center = Vec3::Zero();        ///< m
  int major_segments = 32;           ///< around the axis, >= 3
  int minor_segments = 16;           ///< around the tube, >= 3
};

/// `mesh.tube`: a thick tube along z (a cylinder with a coaxial hole).
struct TubeSpec {
  double inner_radius = 0.5;         ///< m, > 0, < outer_radius
  double outer_radius = 1.0;         ///< m
  double height = 1.0;               ///< m, > 0
  Vec3 center = Vec3::Zero();        ///< m
  int segments = 32;                 ///< around the axis, >= 3
};

/// `mesh.prism`: a profile in the x-z plane (an elevation: outline and holes, e.g. a wall with a
/// door or an arch) extruded along y over `depth`, centred on `y`.
struct PrismSpec {
  std::vector<Vec2> outline;               ///< (x, z) corners of the outer boundary, m, >= 3, either winding
  std::vector<std::vector<Vec2>> holes;    ///< (x, z) corners of each opening, m, inside the outline
  double depth = 0.3;                      ///< extent along y, m, > 0
  double y = 0.0;                          ///< centre of the extent along y, m
};

/// `mesh.file`: a mesh file, transformed as p' = R (scale p) + translate.
struct MeshFileSpec {
  std::string file;                  ///< as written in the case file
  std::filesystem::path path;        ///< resolved path of an existing file
  double scale = 1.0;                ///< uniform, > 0
  Vec3 rotate_deg = Vec3::Zero();    ///< rotations about x, then y, then z, degrees
  Vec3 translate = Vec3::Zero();     ///< m
  /// Repair the mesh into a solid when it is not one (algorithms/repair/); false refuses it instead
  /// (`"repair": false`, or `--no-repair` on the command line).
  bool repair = true;
};

/// What the case's solid is made from.
using MeshSpec = std::variant<BoxSpec, SphereSpec, CylinderSpec, TorusSpec, TubeSpec, PrismSpec, MeshFileSpec>;

/// `appearance`: how the solid looks when rendered (attributes, mesh_attributes.h). A generated mesh
/// with a `surface` material is dressed by box mapping (surface_mapping.h); every solid that carries
/// attributes (also a mesh file's own) gets the `interior` material and the planar UVs of
/// `cap_uv_scale` on its cut faces.
struct AppearanceSpec {
  std::optional<MaterialSlot> surface;   ///< `surface` {name, base_color}: dresses a generated mesh
  double uv_scale = 1.0;                 ///< `uv_scale`: metres per UV unit of the box mapping, > 0
  std::optional<MaterialSlot> interior;  ///< `interior` {name, base_color}: the cut faces' material
  double cap_uv_scale = 0.0;             ///< `cap_uv_scale`: metres per UV unit on cut faces, > 0; 0: default
};

/// `prefracture`: either a fracturer run (`fracturer`, `fragments`, `seed`) or explicit `planes`.
struct PrefractureSpec {
  std::string fracturer = "plane-slice";  ///< registered fracturer name (unchecked here)
  int fragments = 10;                     ///< requested fragments, >= 1
  std::uint64_t seed = 1;                 ///< random seed
  std::vector<Plane> planes;              ///< explicit cuts; when non-empty the fields above are unused
  PluginSettings settings;                ///< `settings` of the fracturer (checked by its factory)

  /// True when the pre-fracture is the explicit list of planes.
  [[nodiscard]] bool explicit_planes() const { return !planes.empty(); }
};

/// One entry of `impacts`: a hit at a frame.
struct ImpactEvent {
  int frame = 1;                     ///< frame index of the hit, 0 <= frame < Case::frames
  Impact impact;                     ///< point (m), unit direction, impulse (N s, >= 0), radius (m, >= 0)
};

/// `runtime`: the fracture done when an impact happens.
struct RuntimeSpec {
  std::string fracturer = "voronoi"; ///< registered fracturer name (unchecked here)
  int fragments = 10;                ///< requested fragments of the hit piece, >= 1
  PluginSettings settings;           ///< `settings` of the fracturer (checked by its factory)
};

/// `stress`: the stress model and its settings.
struct StressSpec {
  std::string model = "von-mises";   ///< registered stress model name (unchecked here)
  PluginSettings settings;           ///< `settings` of the model, e.g. the solver's tolerance (checked by its factory)
};

/// The settings a run gives plugin `chosen`: `settings` when `chosen` is the case's own `named`
/// plugin, none (its defaults) when a command-line option picked another one.
inline const PluginSettings& settings_for(std::string_view chosen, std::string_view named,
                                          const PluginSettings& settings) {
  static const PluginSettings none;
  return chosen == named ? settings : none;
}

/// `grid`: the fragment counts swept by `shatterbench grid`.
struct GridSpec {
  std::vector<int> prefracture = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100};  ///< pre-fracture counts, each >= 1
  std::vector<int> runtime = {5, 10, 15, 20, 25};                             ///< runtime counts, each >= 1
};

/// `needs`: the pipeline results the case asks for; the pipeline runs the stages that lead to them.
struct Needs {
  bool fragments = true;             ///< pre-fracture and runtime fracture
  bool bonds = true;                 ///< the support graph
  bool stress = true;                ///< the stress solve and propagation
  bool colliders = true;             ///< convex hulls and mass properties for physics
  bool physics = true;               ///< the rigid-body steps

  /// The names of the needs that are set, in contract order.
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> out;
    if (fragments) out.emplace_back("fragments");
    if (bonds) out.emplace_back("bonds");
    if (stress) out.emplace_back("stress");
    if (colliders) out.emplace_back("colliders");
    if (physics) out.emplace_back("physics");
    return out;
  }
};

/// `schedule.mode`: when the runtime event's work is done (docs/pipeline.md section 6).
enum class ScheduleMode {
  immediate,  ///< all of it in the frame the impact lands in
  prefetch,   ///< the fracture when the trigger fires (prefetch_frames before the impact), the rest on impact
  amortized,  ///< cut into indivisible steps, spread over frames under a per-frame work budget
};

/// The mode's name in case files, flags and results: "immediate", "prefetch", "amortized".
std::string_view schedule_mode_name(ScheduleMode mode);

/// The mode named `name`, or none when unknown.
std::optional<ScheduleMode> schedule_mode_from_name(std::string_view name);

/// `schedule`: how the runtime event is scheduled over frames.
struct ScheduleSpec {
  ScheduleMode mode = ScheduleMode::immediate;  ///< `mode`
  int prefetch_frames = 2;                      ///< frames from the trigger to the impact (prefetch), >= 0
  double work_budget_ms = 4.0;                  ///< event work per frame (amortized), ms, >= 0 (0: one step a frame)
  /// New bodies an event puts into the world per frame, whole hit fragments at a time (at least one
  /// a frame), the rest in the frames after; 0: all at once. >= 0.
  int max_new_bodies_per_frame = 0;
};

/// `fade_out`: small runtime pieces shrink and leave the physics world (off without the key).
struct FadeOutSpec {
  bool enabled = false;              ///< the key is present
  double max_volume = 0.0;           ///< `volume`: pieces below this volume fade, m^3, >= 0
  int lifetime_frames = 60;          ///< frames a fading piece stays in the world, >= 1
};

/// `debris`: dust particles per event (off without the key).
struct DebrisSpec {
  bool enabled = false;              ///< the key is present
  double per_area = 0.0;             ///< particles per m^2 of new cut area, >= 0
  int per_impact = 0;                ///< particles per impact that fractures something, >= 0
  double speed = 3.0;                ///< initial speed, m/s, >= 0
  int lifetime_frames = 90;          ///< frames a particle lives, >= 1
};

/// `colliders`: how the physics world builds a fragment's collision shape (every field optional).
struct CollidersSpec {
  /// `vertex_budget`: at most this many points per collider, the piece's points extreme along a
  /// fixed spread of directions (harness/pipeline/physics/collider_points.h); 0 = every hull point.
  /// An approximation: its error is `accuracy`'s colliders family. 0 or 4..256.
  int vertex_budget = 0;
};

/// A loaded, checked case. Units are SI.
struct Case {
  std::string name;                        ///< `name`; defaults to the case file's stem
  std::string description;                 ///< `description`, one line; may be empty
  std::filesystem::path source;            ///< the case file it was read from (for messages)
  MeshSpec mesh;                           ///< `mesh` (required)
  Material material;                       ///< `material`; every field optional
  AppearanceSpec appearance;               ///< `appearance`; every field optional
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);    ///< m/s^2
  std::vector<Aabb> anchors;               ///< `anchors[i].box`, m; a fragment overlapping one is fixed
  PrefractureSpec prefracture;             ///< `prefracture`
  std::vector<ImpactEvent> impacts;        ///< `impacts`, in file order
  RuntimeSpec runtime;                     ///< `runtime`
  StressSpec stress;                       ///< `stress`
  int frames = 300;                        ///< frames simulated per run, >= 1 (1/60 s each)
  double budget_ms = 33.3;                 ///< frame-time budget, ms, > 0
  GridSpec grid;                           ///< `grid`
  Needs needs;                             ///< `needs`
  ScheduleSpec schedule;                   ///< `schedule`
  FadeOutSpec fade_out;                    ///< `fade_out`
  DebrisSpec debris;                       ///< `debris`
  CollidersSpec colliders;                 ///< `colliders`
};

}  // namespace shatter
