#include "harness/report/gnuplot_runner.h"

#include "harness/process/child_process.h"

#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

namespace shatter {

std::string gnuplot_program() {
  if (const char* env = std::getenv("SHATTER_GNUPLOT"); env && *env) return env;
  return "gnuplot";
}

Status run_gnuplot(const std::filesystem::path& folder, const std::string& script) {
  const std::string program = gnuplot_program();
  const std::filesystem::path log = std::filesystem::absolute(folder / (script + ".log"));
  ChildOptions options;
  options.working_folder = folder;
  options.stdout_file = "/dev/null";
  options.stderr_file = log;
  Result<ChildExit> run = run_child({program, script}, options);
  const std::string install = "cannot run " + program + ": install gnuplot-nox (scripts/install-deps) or set SHATTER_GNUPLOT";
  if (!run) return Error{install + " (" + run.error().message + ")"};
  std::string first_line;
  {
    std::ifstream in(log);
    std::getline(in, first_line);
  }
  if (!run->exited || run->code != 0) {
    if (run->exited && run->code == 127) return Error{install};
    return Error{program + " failed on " + script + (first_line.empty() ? "" : ": " + first_line)};
  }
  std::error_code ec;
  if (std::filesystem::file_size(log, ec) == 0) std::filesystem::remove(log, ec);
  return {};
}

}  // namespace shatter
