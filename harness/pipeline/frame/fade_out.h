#pragma once
/// Fade-out of small runtime pieces (case key fade_out, docs/pipeline.md section 6): a piece that
/// entered the world in frame v is scaled by 1 - k / lifetime in frame v + k and removed in frame
/// v + lifetime, before that frame's physics step.

#include "harness/pipeline/run_state.h"
#include "harness/pipeline/stage.h"

namespace shatter {

/// The stage fade-out time is reported under: `colliders` (a fade-out edits colliders: it scales and
/// removes them), so the results keep their nine stages and their keys.
inline constexpr Stage kFadeOutReportedAs = Stage::colliders;

/// Scales or removes every fading piece of `run` for frame `run.frame` (needs a physics world), counting
/// removals in RunResult::faded; timed under kFadeOutReportedAs. Nothing (not even a timer) without
/// fading pieces.
void fade_out(RunState& run);

}  // namespace shatter
