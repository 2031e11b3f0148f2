#include "harness/plugins/setting_overrides.h"

#include <cerrno>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace shatter {
namespace {

/// `text` as a setting value: a flag, a finite number read whole, or the text itself.
SettingValue value_of(const std::string& text) {
  if (text == "true") return true;
  if (text == "false") return false;
  if (!text.empty() && text.find_first_of(" \t\n") == std::string::npos) {
    errno = 0;
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    const bool hex_or_word = text.find_first_of("xXnN") != std::string::npos;  // 0x1p3, nan, inf
    if (end == text.c_str() + text.size() && errno == 0 && std::isfinite(x) && !hex_or_word) return x;
  }
  return text;
}

bool snake_case(const std::string& key) {
  if (key.empty() || !(key[0] >= 'a' && key[0] <= 'z')) return false;
  for (const char c : key)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

/// The factory `inner` with `fixed` replacing the same keys of the settings it is given.
template <class Factory>
Factory overridden(Factory inner, PluginSettings fixed) {
  return Factory([inner = std::move(inner), fixed = std::move(fixed)](const PluginSettings& given) {
    PluginSettings merged = given;
    for (const auto& [key, value] : fixed) merged[key] = value;
    return inner(merged);
  });
}

}  // namespace

Result<SettingOverrides> parse_setting_overrides(const std::vector<std::string>& values) {
  SettingOverrides out;
  for (const std::string& text : values) {
    const std::string at = "--set " + text + ": ";
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) return Error{at + "expected NAME.KEY=VALUE (no '=')"};
    const std::string target = text.substr(0, equals);
    const std::size_t dot = target.rfind('.');
    if (dot == std::string::npos || dot == 0) return Error{at + "expected NAME.KEY=VALUE (no algorithm name before a '.')"};
    const std::string name = target.substr(0, dot);
    const std::string key = target.substr(dot + 1);
    if (!snake_case(key)) return Error{at + "the key '" + key + "' is not snake_case (a-z, 0-9, '_')"};
    if (text.find_first_of("\n\r") != std::string::npos) return Error{"--set: a value may not hold a line break"};
    PluginSettings& settings = out[name];
    if (settings.contains(key)) return Error{at + name + "." + key + " is set twice"};
    settings[key] = value_of(text.substr(equals + 1));
  }
  return out;
}

std::string setting_value_text(const SettingValue& value) {
  if (const bool* flag = std::get_if<bool>(&value)) return *flag ? "true" : "false";
  if (const double* number = std::get_if<double>(&value)) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", *number);
    return buffer;
  }
  return std::get<std::string>(value);
}

Status apply_setting_overrides(Registries& registries, const SettingOverrides& overrides) {
  for (const auto& [name, settings] : overrides) {
    const bool fracturer = registries.fracturers.contains(name);
    const bool model = registries.stress_models.contains(name);
    if (!fracturer && !model)
      return Error{"--set " + name + ".*: no fracturer or stress model is named '" + name + "' (see `shatterbench list`)"};
    const PluginSettings fixed = settings;
    const auto wrap_one = [&](auto& registry) {
      registry.wrap_factories([&](const std::string& registered, auto factory) {
        return registered == name ? overridden(std::move(factory), fixed) : std::move(factory);
      });
    };
    if (fracturer) wrap_one(registries.fracturers);
    if (model) wrap_one(registries.stress_models);
    // Checked now, with no other settings: the plugin's own refusal, as for a case file's settings.
    if (fracturer)
      if (auto made = registries.fracturers.create(name); !made) return Error{"--set: " + made.error().message, made.error().cause};
    if (model)
      if (auto made = registries.stress_models.create(name); !made) return Error{"--set: " + made.error().message, made.error().cause};
  }
  return {};
}

}  // namespace shatter
