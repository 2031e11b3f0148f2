#pragma once
/// A plugin's `settings` object of a case file as PluginSettings (algorithms/core/plugin_settings.h).
/// Only the value types are checked here; the plugin's factory checks the keys and their ranges.

#include "algorithms/core/plugin_settings.h"
#include "harness/cases/json_reader.h"

#include <nlohmann/json.hpp>

#include <string_view>

namespace shatter {

/// Reads member "settings" of `obj` (at `parent`) into `out` when present: an object whose values are
/// numbers, true or false, or strings; anything else is an error naming the key path
/// ("prefracture.settings.resolution: expected a number, true/false or a string, got array").
void read_plugin_settings(JsonReader& r, const nlohmann::json& obj, std::string_view parent, PluginSettings& out);

}  // namespace shatter
