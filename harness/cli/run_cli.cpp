#include "harness/cli/run_cli.h"

#include "harness/cli/command.h"
#include "harness/cli/numeric_flags.h"
#include "harness/results/run_context.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

namespace shatter {

int run_cli(int argc, char** argv, const Registries& registries) {
  using namespace cli;
  CLI::App app{"shatterbench: benchmark and regression harness for real-time destruction algorithms",
               "shatterbench"};
  app.require_subcommand(1);
  int exit_code = exit_ok;
  add_list_command(app, exit_code, registries);
  add_fracture_command(app, exit_code, registries);
  add_stress_command(app, exit_code, registries);
  add_grid_command(app, exit_code, registries);
  add_compare_command(app, exit_code);
  add_merge_command(app, exit_code);
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
    std::fprintf(stderr, "shatterbench: internal error: %s\n", e.what());
    return 3;
  }
  // Output that did not reach its destination (a full disk, a closed pipe) is not a success.
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout))
    return fail_input(std::string("cannot write to standard output: ") + std::strerror(errno ? errno : EIO));
  return exit_code;
}

}  // namespace shatter
