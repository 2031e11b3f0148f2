#pragma once
/// Fracturers chosen by what they can do (Fracturer::plane_cutting, cut_plan_replay, exact_reference),
/// never by name: whoever registered them (built-in, a program's own, a plugin), the harness asks.

#include "algorithms/core/plugin_settings.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/fracture/fracturer_registry.h"

#include <memory>
#include <string_view>

namespace shatter {

/// The fracturer that cuts explicit planes: the one registered as `preferred` (made with `settings`)
/// when it offers plane_cutting(), else the first registered fracturer, in registration order, that
/// offers it (default settings). Error when none does; a `preferred` that is not registered or whose
/// settings it refuses is passed over.
Result<std::unique_ptr<Fracturer>> plane_cutter(const FracturerRegistry& fracturers, std::string_view preferred = {},
                                                const PluginSettings& settings = {});

/// The exact reference that replays cut plans: the first registered fracturer, in registration order,
/// that is an exact_reference() and offers cut_plan_replay(). Error when none does.
Result<std::unique_ptr<Fracturer>> plan_replayer(const FracturerRegistry& fracturers);

}  // namespace shatter
