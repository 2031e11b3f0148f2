#include "algorithms/core/plugin_settings.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace shatter {
namespace {

/// Shortest text that reads back as `v` ("8", "0.5", "1e-09").
std::string number_text(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  for (int precision = 1; precision <= 17; ++precision) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", precision, v);
    if (std::strtod(shorter, nullptr) == v) return shorter;
  }
  return buffer;
}

std::string value_text(const SettingValue& value) {
  if (const double* d = std::get_if<double>(&value)) return number_text(*d);
  if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  return "\"" + std::get<std::string>(value) + "\"";
}

const char* type_name(const SettingValue& value) {
  if (std::holds_alternative<double>(value)) return "number";
  if (std::holds_alternative<bool>(value)) return "flag";
  return "string";
}

}  // namespace

std::string settings_text(const PluginSettings& settings) {
  std::string out;
  for (const auto& [key, value] : settings) out += (out.empty() ? "" : " ") + key + "=" + value_text(value);
  return out;
}

SettingsReader::SettingsReader(std::string_view plugin, const PluginSettings& settings,
                               std::span<const SettingDoc> docs)
    : plugin_(plugin), settings_(settings), docs_(docs) {}

Error SettingsReader::error(std::string_view key, std::string_view what) const {
  return Error{plugin_ + ": settings." + std::string(key) + ": " + std::string(what)};
}

const SettingValue* SettingsReader::find(std::string_view key) const {
  const auto it = settings_.find(key);
  return it == settings_.end() ? nullptr : &it->second;
}

Status SettingsReader::check_keys() const {
  for (const auto& [key, value] : settings_) {
    bool known = false;
    for (const SettingDoc& d : docs_) known = known || d.key == key;
    if (known) continue;
    std::string names;
    for (const SettingDoc& d : docs_) names += (names.empty() ? "" : ", ") + d.key;
    return error(key, "unknown key (known: " + (names.empty() ? std::string("none") : names) + ")");
  }
  return {};
}

Status SettingsReader::number(std::string_view key, double min, double max, double& out) const {
  const SettingValue* v = find(key);
  if (!v) return {};
  const double* d = std::get_if<double>(v);
  if (!d) return error(key, std::string("expected a number, got ") + type_name(*v));
  if (!std::isfinite(*d) || *d < min || *d > max)
    return error(key, "must be in [" + number_text(min) + ", " + number_text(max) + "], got " + number_text(*d));
  out = *d;
  return {};
}

Status SettingsReader::number_above(std::string_view key, double min, double max, double& out) const {
  const SettingValue* v = find(key);
  if (!v) return {};
  const double* d = std::get_if<double>(v);
  if (!d) return error(key, std::string("expected a number, got ") + type_name(*v));
  if (!std::isfinite(*d) || *d <= min || *d > max)
    return error(key, "must be in (" + number_text(min) + ", " + number_text(max) + "], got " + number_text(*d));
  out = *d;
  return {};
}

Status SettingsReader::integer(std::string_view key, int min, int max, int& out) const {
  const SettingValue* v = find(key);
  if (!v) return {};
  const double* d = std::get_if<double>(v);
  if (!d || std::floor(*d) != *d)
    return error(key, std::string("expected an integer, got ") + (d ? number_text(*d) : type_name(*v)));
  if (*d < min || *d > max)
    return error(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + number_text(*d));
  out = static_cast<int>(*d);
  return {};
}

Status SettingsReader::flag(std::string_view key, bool& out) const {
  const SettingValue* v = find(key);
  if (!v) return {};
  const bool* b = std::get_if<bool>(v);
  if (!b) return error(key, std::string("expected true or false, got ") + type_name(*v));
  out = *b;
  return {};
}

}  // namespace shatter
