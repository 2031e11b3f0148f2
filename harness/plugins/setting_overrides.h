#pragma once
/// Plugin settings from the command line: `--set NAME.KEY=VALUE` (docs/cli.md, "--set").
///
/// Design note: a case file gives settings only to the algorithms it names, and a command-line option
/// that picks another algorithm gives that one its defaults. `--set` reaches every algorithm by name,
/// whichever command or case creates it: the factories of the named algorithms are wrapped so that
/// the keys given here replace the same keys of whatever settings the caller passes (a case file's,
/// an accuracy sweep's). Each override is checked once, before the command runs, by creating the
/// algorithm with it: an unknown key or a value out of range is the plugin's own one-line refusal.

#include "algorithms/core/plugin_settings.h"
#include "algorithms/core/result.h"
#include "algorithms/registry/registries.h"

#include <map>
#include <string>
#include <vector>

namespace shatter {

/// Algorithm name -> the keys set for it.
using SettingOverrides = std::map<std::string, PluginSettings, std::less<>>;

/// Reads `--set` values "NAME.KEY=VALUE": NAME a registered name (it may hold '.', the last '.'
/// before '=' ends it), KEY snake_case, VALUE `true`, `false`, a finite number, or any other text
/// without a line break.
/// Error "--set TEXT: ..." for a malformed one or a key set twice.
Result<SettingOverrides> parse_setting_overrides(const std::vector<std::string>& values);

/// `value` as `--set` reads it back: `true`, `false`, the number with every digit, or the text.
std::string setting_value_text(const SettingValue& value);

/// Wraps the factories of the algorithms `overrides` names in `registries` as above, then creates each
/// once with its overrides to check them. Error "--set NAME...: ..." for a name that is neither a
/// fracturer nor a stress model, or the factory's refusal.
Status apply_setting_overrides(Registries& registries, const SettingOverrides& overrides);

}  // namespace shatter
