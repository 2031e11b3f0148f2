#pragma once
/// One runtime event (an impact and everything it sets off) as a sequence of phases, each run in one or
/// more indivisible steps (docs/pipeline.md section 6). The phases themselves are in event_phases.h;
/// this header holds the event's data, the order of the phases and the events of a case.

#include "algorithms/fracture/fracturer.h"
#include "harness/cases/case.h"

#include <vector>

namespace shatter {

/// What a runtime event does next, in order. A phase a run does not need is passed over (see
/// phase_after).
enum class EventPhase {
  fracture,          ///< choose the hit fragments, then fracture one of them per step
  bond_update,       ///< break every bond of the hit fragments (skipped without bonds)
  stress,            ///< the stress cascade, one step
  falling_clusters,  ///< standing components that lost every anchor
  colliders,         ///< prepare bodies: a batch of pieces, or one falling cluster, per step (needs a world)
  make_visible,      ///< the result enters the world: old static bodies out, new bodies in, debris spawned
  done,              ///< nothing left to do
};

/// Number of phases, `done` included.
inline constexpr int kEventPhaseCount = 7;

/// What decides which phases an event runs.
struct EventRoute {
  bool bonds = true;   ///< the run has bonds (bond update, stress and falling clusters run)
  bool world = true;   ///< the run has a physics world (colliders are prepared)
};

/// The phase that follows a finished `phase` on `route`: fracture, bond update, then stress and falling
/// clusters when there are bonds, colliders when there is a world, make visible, done.
EventPhase phase_after(EventPhase phase, const EventRoute& route);

/// One runtime event from its trigger until its result is in the world.
struct RuntimeEvent {
  const Impact* impact = nullptr;             ///< the impact (borrowed from the case)
  int index = 0;                              ///< event index in landing order (seeds)
  int impact_frame = 0;                       ///< the frame the impact lands in
  int trigger_frame = 0;                      ///< the frame its work may start in
  int visible_frame = -1;                     ///< the frame of its make_visible step, -1 until then or when nothing was hit
  EventPhase phase = EventPhase::fracture;    ///< what it does next
  bool selected = false;                      ///< the hit fragments have been chosen
  std::vector<int> hit_fragments;             ///< standing fragments the impact reaches, ascending
  std::vector<std::vector<Fragment>> pieces;  ///< per hit fragment fractured so far, its pieces
  std::vector<std::vector<int>> falling;      ///< clusters that lost their anchors through this event
  std::vector<int> piece_bodies;              ///< prepared bodies of the pieces, flat, in piece order
  std::vector<int> cluster_bodies;            ///< prepared bodies of the falling clusters
  std::size_t items_in_world = 0;             ///< hit fragments, then falling clusters, whose bodies are in the world
  int spawn_frame = -1;                       ///< the frame of the last make_visible step
  int spawned_in_frame = 0;                   ///< new bodies that step's frame put into the world
  /// make_visible has reached the frame's cap on new bodies (schedule.max_new_bodies_per_frame): no
  /// schedule steps this event again before `waits_until`.
  int waits_until = -1;
};

/// The events of `impacts` in the order they land (frame, then file order), indexed in that order. An
/// impact after the last of `frames` frames lands in the last. Under `prefetch` an event triggers
/// `prefetch_frames` before its impact (not before frame 0), otherwise in the impact frame.
std::vector<RuntimeEvent> events_in_landing_order(const std::vector<ImpactEvent>& impacts, int frames,
                                                  ScheduleMode mode, int prefetch_frames);

}  // namespace shatter
