#include "harness/cli/run_cli.h"

#include "harness/plugins/plugin_guard.h"
#include "harness/signals/interrupt_cleanup.h"

#include "harness/cli/command.h"
#include "harness/cli/numeric_flags.h"
#include "harness/plugins/plugin_loader.h"
#include "harness/plugins/setting_overrides.h"
#include "harness/results/run_context.h"

#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {
namespace {

/// argv without its `--plugin PATH` and `--set NAME.KEY=VALUE` options (also as `--plugin=PATH`,
/// `--set=...`; before a "--"), and their values.
struct PluginArguments {
  std::vector<char*> argv;
  std::vector<std::string> paths;
  std::vector<std::string> sets;
  std::string error;  ///< a --plugin or --set without its value
};

PluginArguments take_plugin_arguments(int argc, char** argv) {
  PluginArguments out;
  // The options taken here: `--NAME VALUE` or `--NAME=VALUE`, each value into its list.
  struct Taken {
    std::string_view flag;
    std::vector<std::string>* values;
    const char* needs;
  };
  const Taken taken[] = {{"--plugin", &out.paths, "--plugin needs the path of a plugin library"},
                         {"--set", &out.sets, "--set needs NAME.KEY=VALUE"}};
  bool options = true;
  for (int i = 0; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (i == 0 || !options) {
      out.argv.push_back(argv[i]);
      continue;
    }
    if (arg == "--") options = false;
    const Taken* match = nullptr;
    std::string_view value;
    for (const Taken& t : taken) {
      if (arg == t.flag) {
        match = &t;
        value = i + 1 < argc ? std::string_view(argv[++i]) : std::string_view();
      } else if (arg.size() > t.flag.size() && arg.starts_with(t.flag) && arg[t.flag.size()] == '=') {
        match = &t;
        value = arg.substr(t.flag.size() + 1);
      }
      if (match != nullptr) break;
    }
    if (match == nullptr) {
      out.argv.push_back(argv[i]);
      continue;
    }
    if (value.empty()) {
      out.error = match->needs;
      return out;
    }
    match->values->emplace_back(value);
  }
  out.argv.push_back(nullptr);
  return out;
}

/// A run's registries: the program's own and the plugins', with where each plugin's names came from.
struct LoadedRegistries {
  Registries registries;
  PluginOrigins origins;
};

/// `registries` with the plugins of SHATTERBENCH_PLUGIN_PATH and of `flags` (in that order) added.
/// The plugins loaded are left in SHATTERBENCH_PLUGIN_PATH, so a child this process runs (the
/// callgrind re-run of `grid --metric instructions`) loads the same ones.
Result<LoadedRegistries> with_plugins(const Registries& registries, const std::vector<std::string>& flags) {
  // The program's own registrations keep the rules a plugin's must (Registry::problem).
  if (std::string problem = registries.fracturers.problem(); !problem.empty()) return Error{"registry: " + problem};
  if (std::string problem = registries.stress_models.problem(); !problem.empty()) return Error{"registry: " + problem};
  std::vector<std::string> paths;
  const char* variable = std::getenv("SHATTERBENCH_PLUGIN_PATH");
  if (variable != nullptr) {
    Result<std::vector<std::string>> listed = plugin_path_files(variable);
    if (!listed) return listed.error();
    paths = *listed;
  }
  LoadedRegistries all{registries, {}};
  // The built-ins' results pass the checks a plugin's do (plugin_guard.h), at the same cost.
  guard_registrations(all.registries);
  if (paths.empty() && flags.empty()) return all;
  std::string joined;
  for (const std::string& flag : flags) {
    if (flag.find(':') != std::string::npos)
      return Error{"--plugin " + flag + ": a plugin path may not hold ':' (the separator of SHATTERBENCH_PLUGIN_PATH)"};
    paths.push_back(flag);
  }
  if (Status s = load_plugins(paths, all.registries, all.origins); !s) return s.error();
  if (!flags.empty()) {
    for (const std::string& path : paths) joined += (joined.empty() ? "" : ":") + path;
    ::setenv("SHATTERBENCH_PLUGIN_PATH", joined.c_str(), 1);
  }
  return all;
}

/// The `--set` values of SHATTERBENCH_SET (one per line) with those of `flags` over them. The flags
/// are left in SHATTERBENCH_SET (as the plugins in SHATTERBENCH_PLUGIN_PATH), so a child this process
/// runs (the callgrind re-run of `grid --metric instructions`) sets the same keys.
Result<SettingOverrides> setting_overrides(const std::vector<std::string>& flags) {
  std::vector<std::string> inherited;
  const char* variable = std::getenv("SHATTERBENCH_SET");
  for (std::string_view rest = variable != nullptr ? variable : ""; !rest.empty();) {
    const std::size_t end = rest.find('\n');
    if (end != 0) inherited.emplace_back(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  }
  Result<SettingOverrides> merged = parse_setting_overrides(inherited);
  if (!merged) return Error{"SHATTERBENCH_SET: " + merged.error().message};
  Result<SettingOverrides> given = parse_setting_overrides(flags);
  if (!given) return given.error();
  for (const auto& [name, settings] : *given)
    for (const auto& [key, value] : settings) (*merged)[name][key] = value;
  if (!flags.empty()) {
    std::string joined;
    for (const auto& [name, settings] : *merged)
      for (const auto& [key, value] : settings) joined += name + "." + key + "=" + setting_value_text(value) + "\n";
    ::setenv("SHATTERBENCH_SET", joined.c_str(), 1);
  }
  return merged;
}

}  // namespace

int run_cli(int argc, char** argv, const Registries& builtin) {
  // An interrupt ends the children this command starts and removes its temporaries (unless the
  // program calling run_cli handles the signals itself).
  install_interrupt_cleanup();
  using namespace cli;
  PluginArguments arguments = take_plugin_arguments(argc, argv);
  if (!arguments.error.empty()) return fail_input(arguments.error);
  argc = static_cast<int>(arguments.argv.size()) - 1;
  argv = arguments.argv.data();
  Result<LoadedRegistries> loaded = with_plugins(builtin, arguments.paths);
  if (!loaded) return fail_input(loaded.error().message);
  Result<SettingOverrides> overrides = setting_overrides(arguments.sets);
  if (!overrides) return fail_input(overrides.error().message);
  if (Status s = apply_setting_overrides(loaded->registries, *overrides); !s) return fail_algorithm("", s.error());
  const Registries& registries = loaded->registries;
  CLI::App app{"shatterbench: benchmark and regression harness for real-time destruction algorithms",
               "shatterbench"};
  app.require_subcommand(1);
  // Read before parsing (take_plugin_arguments), declared here for --help.
  std::vector<std::string> plugin_help;
  app.add_option("--plugin", plugin_help,
                 "Load a plugin library with more fracturers and stress models (repeatable; also the "
                 "':'-separated SHATTERBENCH_PLUGIN_PATH); docs/plugins.md");
  std::vector<std::string> set_help;
  app.add_option("--set", set_help,
                 "NAME.KEY=VALUE: a setting of fracturer or stress model NAME wherever the command creates it, "
                 "over the case file's (repeatable; `list` shows each one's keys); docs/cli.md");
  int exit_code = exit_ok;
  add_list_command(app, exit_code, registries, loaded->origins);
  add_fracture_command(app, exit_code, registries);
  add_stress_command(app, exit_code, registries);
  add_grid_command(app, exit_code, registries);
  add_compare_command(app, exit_code);
  add_merge_command(app, exit_code);
  add_history_command(app, exit_code);
  add_table_command(app, exit_code, registries);
  add_accuracy_command(app, exit_code, registries);
  add_report_command(app, exit_code);
  add_stability_command(app, exit_code, registries);
  check_numeric_flags(app);  // every numeric flag read strictly: no nan, inf, wrap or saturation
  if (argc == 2 && std::string(argv[1]) == "--version") {
    // Version, the commit built and the context fingerprint that results carry (docs/results.md).
    const RunContext c = current_context();
    std::printf("shatterbench %s\ncommit %s\nbuild %s, %s, %s; CGAL %s, Eigen %s, Bullet %s\nfingerprint %s\n",
                shatterbench_version().c_str(), c.commit.empty() ? "unknown" : c.commit.c_str(), c.build_type.c_str(),
                c.compiler.c_str(), c.flags.c_str(), c.cgal_version.c_str(), c.eigen_version.c_str(),
                c.bullet_version.c_str(), c.fingerprint.c_str());
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
      return fail_input(std::string("cannot write to standard output: ") + std::strerror(errno ? errno : EIO));
    return exit_ok;
  }
  if (argc > 1 && argv[1][0] != '-') {
    // CLI11 would only say that a subcommand is required: name the word and the commands instead.
    std::string known;
    bool found = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      known += (known.empty() ? "" : ", ") + sub->get_name();
      found = found || sub->get_name() == argv[1];
    }
    if (!found) return fail_input(std::string("unknown command \"") + argv[1] + "\" (commands: " + known + ")");
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return exit_ok;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return exit_ok;
  } catch (const CLI::ParseError& e) {
    // Subcommand --help arrives here too (CLI11 raises CallForHelp from the subcommand).
    if (e.get_exit_code() == 0) return app.exit(e);
    return fail_input(e.what());
  } catch (const std::exception& e) {
    // fmt::print throws when standard output refuses a write (a full disk, a closed pipe) before the
    // check below could see it: the same bad destination, the same answer.
    if (std::ferror(stdout))
      return fail_input(std::string("cannot write to standard output: ") + std::strerror(errno ? errno : EIO));
    std::fprintf(stderr, "shatterbench: internal error: %s\n", one_printable_line(e.what()).c_str());
    return exit_internal_error;
  } catch (...) {
    std::fprintf(stderr, "shatterbench: internal error: an exception that is not a std::exception\n");
    return exit_internal_error;
  }
  // Output that did not reach its destination (a full disk, a closed pipe) is not a success.
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout))
    return fail_input(std::string("cannot write to standard output: ") + std::strerror(errno ? errno : EIO));
  return exit_code;
}

}  // namespace shatter
