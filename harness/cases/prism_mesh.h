#pragma once
/// The `prism` mesh of a case file: an elevation profile with openings, extruded into a solid.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "harness/cases/case.h"
#include "harness/cases/json_reader.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace shatter {

/// Reads `{"outline": [[x, z], ...], "holes": [[[x, z], ...], ...], "depth": d, "y": y}` at `path`.
PrismSpec read_prism(JsonReader& reader, const nlohmann::json& value, std::string_view path);

/// The closed solid of `spec`: the profile triangulated (constrained Delaunay, openings excluded) as
/// the front (y - depth/2, facing -y) and back faces, joined by one quad per profile edge. Errors name
/// `what` when the profile crosses itself or has no area.
Result<Mesh> make_prism(const PrismSpec& spec, const std::string& what);

}  // namespace shatter
