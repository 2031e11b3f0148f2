#pragma once
/// The documented limits of the harness (docs/limits.md): every count a case file or a flag controls
/// that sizes what a run allocates or keeps. A value past one is refused before anything runs, with
/// one line naming the key or the flag and the limit (exit 2 from the CLI). The mesh readers' limits
/// are in algorithms/core/mesh_limits.h, the fragment limit in algorithms/fracture/fracture_limits.h.
///
/// Design note: each number is far above what a benchmark of real-time destruction asks for (the
/// default grid is 10 x 5 cells, 3 repetitions, 300 frames) and far below what would exhaust the
/// benchmark machine. A limit turns a typo or a generated file gone wrong into a message instead of
/// an allocation that runs the machine out of memory an hour into a run.

#include <cstddef>
#include <cstdint>

namespace shatter {

/// Frames per run (`frames`, `grid --frames`): 100,000 frames are 28 minutes at 60 Hz, where a
/// destruction scene lasts seconds; every frame is kept per repetition (8 bytes, about 20 in JSON).
inline constexpr int kMaxFrames = 100'000;

/// Repetitions per cell (`--repetitions` of grid, table, accuracy): the rank test of `compare` needs 9;
/// a thousand of the default grid's largest cell is already hours.
inline constexpr int kMaxRepetitions = 1'000;

/// Cells per grid: pre-fracture counts x runtime counts (`grid.prefracture` x `grid.runtime`, or the
/// flags): 200 times the default 10 x 5 grid, a 100 x 100 sweep.
inline constexpr std::int64_t kMaxGridCells = 10'000;

/// Frames a grid records: cells (of this shard) x repetitions x frames. The results keep every one,
/// with its stage times: 8 bytes a frame and 8 per stage that ran inside frames (56 with the building
/// case's 6), about 450 MB in memory and 51 bytes a frame, about 410 MB, of JSON at the limit
/// (docs/limits.md says how it was measured).
inline constexpr std::int64_t kMaxRecordedFrames = 8'000'000;

/// Poses a grid records with `--record-frames` (harness/results/recorded_frames.h): the bodies of each
/// recorded run times its frames, summed over the recorded cells. A pose is 20 bytes in the sidecar
/// file and about 40 in memory while the run records: 40 MB and 80 MB at the limit, over 13 times a
/// scene of 500 bodies over 300 frames. Checked after each frame, as bodies appear; the run stops at
/// the first frame past it.
inline constexpr std::int64_t kMaxRecordedPoses = 2'000'000;

/// The 3D views of one report (`report` with fragments folders, docs/report.md "Limits"): at most this
/// many fragments and triangles over every folder it embeds; past either, the report is refused with
/// one line (the page would pass tens of megabytes and draw too slowly to orbit). A 1 M-triangle mesh
/// fractured is past it: show it with fewer or smaller meshes.
inline constexpr std::int64_t kMaxReportFragments = 5'000;
inline constexpr std::int64_t kMaxReportTriangles = 500'000;
/// The recorded frames one report embeds for playback (`grid --record-frames` sidecars), bytes.
inline constexpr std::uint64_t kMaxReportRecordingBytes = 16ULL << 20;

/// Runtime pieces one run can make: pre-fracture count x runtime count of a cell (every fragment
/// hit). Each piece is a mesh, a convex hull and a rigid body, a few KB: about 5 GB at the limit.
inline constexpr std::int64_t kMaxRunPieces = 1'000'000;

/// Segments and rings of a primitive mesh (`segments`, `rings`, `major_segments`, `minor_segments`);
/// their product is also held to kMaxMeshTriangles (a 4096 x 4096 sphere would be 33 M triangles).
inline constexpr int kMaxPrimitiveSegments = 4096;

/// Size of a case file: the loader holds the text and its JSON tree (about ten times the text); the
/// built-in cases are 1 to 2 KB. It also bounds the lists without a limit of their own (anchors).
inline constexpr std::uint64_t kMaxCaseFileBytes = 16ULL << 20;

/// Bytes of a case name: the name is a file name (results/baselines/<name>.json), and file systems
/// allow 255 bytes for one, less the `.json` and the `.NAME.partial-XXXXXXXX` of an atomic write.
inline constexpr std::size_t kMaxCaseNameBytes = 200;

/// Size of a results file read by compare, merge and report (grid and accuracy JSON), and of an
/// instruction dump read back from valgrind: the reader holds the text and its JSON tree (about ten
/// times the text). A grid at kMaxRecordedFrames writes about 410 MB of JSON; a file past 1 GiB is
/// not one this tool wrote (a link to /dev/zero, a wrong file) and is refused before it is held.
inline constexpr std::uint64_t kMaxResultsFileBytes = 1ULL << 30;

/// Corners of a prism's profile, outline and holes together: a wall's elevation has tens; each corner
/// makes about four triangles (front, back and the side quad), 400,000 at the limit.
inline constexpr int kMaxPrismCorners = 100'000;

/// Explicit pre-fracture planes (`prefracture.planes`): hand-written cuts are a few dozen; the pieces
/// they make are held to kMaxFragments separately (n planes can make about n^3 / 6 pieces).
inline constexpr int kMaxExplicitPlanes = 1'000;

/// Impacts of a case (`impacts`): each is one runtime event whose pieces and particles stay in the
/// world; with kMaxDebrisPerEvent it keeps the particle counters far inside their range.
inline constexpr int kMaxImpacts = 1'000;

/// Debris particles one event spawns (`debris.per_impact`; `per_area` x cut area is clamped to it).
inline constexpr int kMaxDebrisPerEvent = 100'000;

/// Debris particles alive at once (52 bytes each, 52 MB at the limit); an event spawns no more than
/// the room left (`particles_spawned` counts what was spawned).
inline constexpr int kMaxDebrisParticles = 1'000'000;

/// The range a physical quantity of a case file must lie in (bounds inclusive unless marked open).
struct PhysicalRange {
  double min = 0.0;          ///< smallest accepted value
  double max = 0.0;          ///< largest accepted value
  bool max_open = false;     ///< the maximum itself is refused
  const char* unit = "";     ///< unit of the bounds, for messages ("Pa")
};

// Physical ranges. Each is far wider than any real material or scene, and narrow enough that every
// product the solve and the physics form (stiffness x length, density x volume x gravity, impulse /
// mass) stays many orders of magnitude inside double: E = 1e300 or gravity 1e308 overflow there and
// give Inf, NaN or all-zero forces, E = 1e-300 underflows. A value outside is refused at case load,
// with one line naming the key (tests/hostile/wrong_answers_numbers_tests.cpp).

/// `material.density`, kg/m^3: aerogels weigh about 1, osmium 22,590.
inline constexpr PhysicalRange kDensityRange{1e-1, 1e5, false, "kg/m^3"};
/// `material.young_modulus`, Pa: gels and soft foams about 1e4, diamond 1.2e12.
inline constexpr PhysicalRange kYoungModulusRange{1e3, 1e13, false, "Pa"};
/// `material.poisson_ratio`: [0, 0.5); 0.5 (incompressible) makes the shear terms singular.
inline constexpr PhysicalRange kPoissonRatioRange{0.0, 0.5, true, ""};
/// `material.*_strength`, Pa: snow and foams about 1e3 to 1e5, graphene 1.3e11.
inline constexpr PhysicalRange kStrengthRange{1e2, 1e12, false, "Pa"};
/// Each component of `gravity`, m/s^2: the Sun's surface is 274; 1e5 is 10,000 g.
inline constexpr PhysicalRange kGravityComponentRange{-1e5, 1e5, false, "m/s^2"};
/// `impacts[].impulse`, N s: a car crash is about 1e5.
inline constexpr PhysicalRange kImpulseRange{0.0, 1e9, false, "N s"};
/// Lengths of a case: sizes, radii, heights, depths, impact radii (m): a micrometre to 1,000 km.
inline constexpr PhysicalRange kLengthRange{1e-6, 1e6, false, "m"};
/// `impacts[].radius`, m: 0 (only the fragment hit) up to kLengthRange's maximum.
inline constexpr PhysicalRange kImpactRadiusRange{0.0, 1e6, false, "m"};
/// Each coordinate of a position (centres, translations, anchor boxes, impact points, plane points,
/// prism corners), m: within 1,000 km of the origin.
inline constexpr PhysicalRange kCoordinateRange{-1e6, 1e6, false, "m"};
/// `debris.speed`, m/s: ejecta of an explosion reach a few km/s.
inline constexpr PhysicalRange kDebrisSpeedRange{0.0, 1e4, false, "m/s"};
/// `mesh.scale` of a mesh file: a mesh in micrometres to one in thousands of kilometres.
inline constexpr PhysicalRange kScaleRange{1e-6, 1e6, false, ""};

/// Size of one pre-fracture cache entry (harness/pipeline/prefracture_cache.h), checked before it is
/// read: an entry holds the fragments as raw doubles and indices, 24 bytes a vertex and 13 a triangle,
/// so a 10-million-triangle solid in 1,000 pieces is about 400 MB. A larger entry is a miss, and one
/// that would be larger is not stored.
inline constexpr std::uint64_t kMaxCacheEntryBytes = 1ULL << 30;

/// Size of one texture image that `fracture --out` copies beside the fragments (harness/results/
/// fragment_writer.h): a 16k x 16k RGBA PNG is at most about 1 GiB, a game's textures are a few MB.
inline constexpr std::uint64_t kMaxTextureBytes = 256ULL << 20;

/// Memory of the child process that imports an asset through assimp (harness/cases/isolated_import.h):
/// its address space is limited to this (RLIMIT_AS), so a decompression bomb or a file that claims
/// billions of elements ends that child, not the machine. assimp holds about 3 to 4 times the mesh
/// it builds; a mesh at the reader limits (10 M triangles with attributes) needs about 2 GB.
inline constexpr std::uint64_t kMaxImportMemoryBytes = 8ULL << 30;

/// Wall time of one asset import through assimp, seconds: a million-triangle FBX or glTF takes a few.
inline constexpr double kMaxImportSeconds = 120.0;

/// Memory of the child process that repairs a mesh into a solid (harness/cases/isolated_repair.h):
/// CGAL's hole filling and self-intersection steps grow with the size of a hole or of an overlap, not
/// with the mesh, so a flat polygon of 40,000 corners would exhaust the machine.
inline constexpr std::uint64_t kMaxRepairMemoryBytes = 8ULL << 30;

/// Wall time of one mesh repair, seconds: ten times the slowest repair of the CGAL data set (12.5 s,
/// docs/repair.md).
inline constexpr double kMaxRepairSeconds = 120.0;

}  // namespace shatter
