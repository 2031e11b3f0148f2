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

/// Frames a grid records: cells (of this shard) x repetitions x frames. The results keep every one:
/// 160 MB of doubles in memory and about 400 MB of JSON at the limit.
inline constexpr std::int64_t kMaxRecordedFrames = 20'000'000;

/// Runtime pieces one run can make: pre-fracture count x runtime count of a cell (every fragment
/// hit). Each piece is a mesh, a convex hull and a rigid body, a few KB: about 5 GB at the limit.
inline constexpr std::int64_t kMaxRunPieces = 1'000'000;

/// Segments and rings of a primitive mesh (`segments`, `rings`, `major_segments`, `minor_segments`);
/// their product is also held to kMaxMeshTriangles (a 4096 x 4096 sphere would be 33 M triangles).
inline constexpr int kMaxPrimitiveSegments = 4096;

/// Size of a case file: the loader holds the text and its JSON tree (about ten times the text); the
/// built-in cases are 1 to 2 KB. It also bounds the lists without a limit of their own (anchors).
inline constexpr std::uint64_t kMaxCaseFileBytes = 16ULL << 20;

/// Size of a results file read by compare, merge and report (grid and accuracy JSON), and of an
/// instruction dump read back from valgrind: the reader holds the text and its JSON tree (about ten
/// times the text). A grid at kMaxRecordedFrames writes about 400 MB of JSON; a file past 1 GiB is
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

}  // namespace shatter
