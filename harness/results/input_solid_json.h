#pragma once
/// The `input` block of `fracture`'s JSON and of the grid results: the solid every fracture started
/// from, and what repair did to the user's mesh to make it (docs/repair.md).

#include "harness/cases/load_solid.h"

#include <nlohmann/json.hpp>

namespace shatter {

/// `{"triangles", "volume", "area", "flipped", "repairs": {...}}` of `solid`; see docs/cli.md for the keys.
nlohmann::ordered_json input_solid_json(const Solid& solid);

/// The `repairs` object alone: every count, the added area, the Hausdorff distance and the repair's
/// time (offline: never part of a fracture's time_ms).
nlohmann::ordered_json repairs_json(const Solid& solid);

}  // namespace shatter
