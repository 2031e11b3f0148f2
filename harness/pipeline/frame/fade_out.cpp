#include "harness/pipeline/frame/fade_out.h"

namespace shatter {

void fade_out(RunState& run) {
  if (run.fading.empty()) return;
  StageTimer fade_out_span(run.result.frame_stages, kFadeOutReportedAs);
  const int lifetime = run.spec.fade_out.lifetime_frames;
  std::size_t kept = 0;
  for (const FadingPiece& f : run.fading) {
    const int age = run.frame - f.visible_frame;
    if (age <= 0) {
      run.fading[kept++] = f;
    } else if (age >= lifetime) {
      run.world->remove(f.body);
      ++run.result.faded;
    } else {
      run.world->set_scale(f.body, 1.0 - static_cast<double>(age) / lifetime);
      run.fading[kept++] = f;
    }
  }
  run.fading.resize(kept);
}

}  // namespace shatter
