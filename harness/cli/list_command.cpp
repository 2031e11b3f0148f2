#include "algorithms/registry/registries.h"
#include "harness/cases/case_library.h"
#include "harness/cli/command.h"

#include <fmt/core.h>

namespace shatter::cli {

namespace {

/// Prints one registered plugin: its name and description, the plugin file it came from (when not
/// built in), then one line per documented setting.
void print_plugin(const std::string& name, const std::string& description, std::span<const SettingDoc> settings,
                  const PluginOrigins& origins) {
  fmt::print("  {:<18} {}\n", name, description);
  if (const auto it = origins.find(name); it != origins.end()) fmt::print("    from plugin {}\n", it->second);
  for (const SettingDoc& s : settings)
    fmt::print("    {:<29} {:<12} default {:<10} range {:<16} {}\n", "settings." + s.key, s.unit.empty() ? "-" : s.unit,
               s.default_text, s.range, s.description);
}

}  // namespace

void add_list_command(CLI::App& app, int& exit_code, const Registries& r, const PluginOrigins& origins) {
  CLI::App* cmd = app.add_subcommand(
      "list", "List the registered fracturers, stress models (each with its settings) and built-in cases");
  cmd->callback([&exit_code, &r, &origins] {
    fmt::print("fracturers:\n");
    for (const std::string& name : r.fracturers.names())
      print_plugin(name, r.fracturers.description(name), r.fracturers.settings(name), origins);
    fmt::print("stress models:\n");
    for (const std::string& name : r.stress_models.names())
      print_plugin(name, r.stress_models.description(name), r.stress_models.settings(name), origins);
    fmt::print("built-in cases:\n");
    for (const BuiltinCase& c : list_builtin_cases()) fmt::print("  {:<18} {}\n", c.name, c.description);
    exit_code = exit_ok;
  });
}

}  // namespace shatter::cli
