#pragma once
/// A plugin's settings as given by the user (a case file's `"settings": {...}`), and the documented
/// list of the keys a plugin accepts.
///
/// Design note: the algorithms library does not depend on a JSON library, so settings are a plain
/// key -> value map (number, flag or text) that the harness fills from JSON. A plugin reads its keys
/// through SettingsReader against its own SettingDoc list: an unknown key is an error naming the key
/// (and the known ones), a value of the wrong type or out of range an error naming the key and the
/// range. Absent keys keep the plugin's defaults, so empty settings always mean "the defaults".

#include "algorithms/core/result.h"

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace shatter {

/// One setting's value: a number (JSON integers included), a flag or a text.
using SettingValue = std::variant<double, bool, std::string>;

/// Key -> value, as the user wrote them; empty means every default.
using PluginSettings = std::map<std::string, SettingValue, std::less<>>;

/// What `list` prints about one key a plugin accepts.
struct SettingDoc {
  std::string key;          ///< as written in `settings`, snake_case
  std::string unit;         ///< "m", "s", "Pa", "cells", "" for a dimensionless number or a flag
  std::string default_text; ///< the default, as text ("16", "0.5", "false")
  std::string range;        ///< the accepted values, as text ("[2, 128]", ">= 1", "> 0")
  std::string description;  ///< one line: what the key changes
  /// Values `shatterbench accuracy` sweeps this key over (its accuracy knob); empty for none.
  std::vector<double> accuracy_sweep;
};

/// "key=value" pairs in key order ("resolution=8 impact_share=0.5"); "" for empty settings.
std::string settings_text(const PluginSettings& settings);

/// Reads the settings of one plugin, checking each key against its documented list.
class SettingsReader {
 public:
  /// `plugin` names the plugin in every message; `docs` is its documented key list.
  SettingsReader(std::string_view plugin, const PluginSettings& settings, std::span<const SettingDoc> docs);

  /// Error "<plugin>: settings.<key>: unknown key (known: a, b)" for the first unknown key.
  [[nodiscard]] Status check_keys() const;
  /// Reads a number in [min, max] into `out` (kept when absent); `integer` refuses fractions.
  [[nodiscard]] Status number(std::string_view key, double min, double max, double& out) const;
  /// Reads a number in (min, max] into `out` (kept when absent).
  [[nodiscard]] Status number_above(std::string_view key, double min, double max, double& out) const;
  /// Reads an integer in [min, max] into `out` (kept when absent).
  [[nodiscard]] Status integer(std::string_view key, int min, int max, int& out) const;
  /// Reads a flag into `out` (kept when absent).
  [[nodiscard]] Status flag(std::string_view key, bool& out) const;

 private:
  [[nodiscard]] Error error(std::string_view key, std::string_view what) const;
  [[nodiscard]] const SettingValue* find(std::string_view key) const;
  std::string plugin_;
  const PluginSettings& settings_;
  std::span<const SettingDoc> docs_;
};

}  // namespace shatter
