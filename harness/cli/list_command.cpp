#include "algorithms/registry/register_all.h"
#include "harness/cases/case_library.h"
#include "harness/cli/command.h"

#include <fmt/core.h>

namespace shatter::cli {

void add_list_command(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand("list", "List the registered fracturers, stress models and built-in cases");
  cmd->callback([&exit_code] {
    const Registries& r = registries();
    fmt::print("fracturers:\n");
    for (const std::string& name : r.fracturers.names())
      fmt::print("  {:<18} {}\n", name, r.fracturers.description(name));
    fmt::print("stress models:\n");
    for (const std::string& name : r.stress_models.names())
      fmt::print("  {:<18} {}\n", name, r.stress_models.description(name));
    fmt::print("built-in cases:\n");
    for (const BuiltinCase& c : list_builtin_cases()) fmt::print("  {:<18} {}\n", c.name, c.description);
    exit_code = exit_ok;
  });
}

}  // namespace shatter::cli
