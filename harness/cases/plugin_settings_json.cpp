#include "harness/cases/plugin_settings_json.h"

#include <string>

namespace shatter {

void read_plugin_settings(JsonReader& r, const nlohmann::json& obj, std::string_view parent, PluginSettings& out) {
  if (r.failed() || !obj.is_object() || !obj.contains("settings")) return;
  const std::string at = key_path(parent, "settings");
  const nlohmann::json& settings = obj["settings"];
  if (!settings.is_object()) {
    r.fail(at, std::string("expected an object, got ") + settings.type_name());
    return;
  }
  PluginSettings read;
  for (const auto& [key, value] : settings.items()) {
    const std::string path = key_path(at, key);
    if (value.is_boolean()) {
      read[key] = value.get<bool>();
    } else if (value.is_number()) {
      double number = 0.0;
      if (!r.convert(value, path, number)) return;
      read[key] = number;
    } else if (value.is_string()) {
      read[key] = value.get<std::string>();
    } else {
      r.fail(path, std::string("expected a number, true/false or a string, got ") + value.type_name());
      return;
    }
  }
  out = std::move(read);
}

}  // namespace shatter
