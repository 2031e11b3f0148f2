#pragma once
/// Fracturers by name ("plane-slice", "cgal-clip", ...).

#include "algorithms/core/registry.h"
#include "algorithms/fracture/fracturer.h"

namespace shatter {

template <>
inline constexpr std::string_view plugin_kind<Fracturer> = "fracturer";

/// Name -> fracturer factory table.
using FracturerRegistry = Registry<Fracturer>;
/// Creates a fracturer from its settings.
using FracturerFactory = FracturerRegistry::Factory;

}  // namespace shatter
