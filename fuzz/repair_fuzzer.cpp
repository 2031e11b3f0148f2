/// libFuzzer target: an OFF file made into a solid (read, then repaired when it is not one) must give a
/// solid or a one-line error, never a crash; a solid must pass the acceptance rule again and have a
/// finite, positive volume, and its repair report finite figures.

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_validation.h"
#include "fuzz/fuzz_input_file.h"
#include "harness/cases/load_solid.h"

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const shatter::fuzz::InputFile file(data, size);
  shatter::Result<shatter::Mesh> mesh = shatter::read_off(file.path());
  if (!mesh) return 0;
  shatter::Result<shatter::Solid> solid = shatter::make_solid(std::move(*mesh), "fuzz.off", shatter::SolidRepair::repair_in_process);
  if (!solid) {
    const std::string& m = solid.error().message;
    if (m.empty() || m.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  shatter::Mesh again = solid->mesh;
  if (!shatter::validate_solid(again, "repaired")) std::abort();
  if (!std::isfinite(solid->mass.volume) || !(solid->mass.volume > 0.0)) std::abort();
  const shatter::RepairReport& r = solid->repair;
  if (!std::isfinite(r.hausdorff_distance) || !std::isfinite(r.hole_area) || !std::isfinite(r.time_ms)) std::abort();
  return 0;
}
