#include "harness/cli/progress_line.h"

#include <cstdio>
#include <unistd.h>
#include <utility>

namespace shatter::cli {

ProgressLine::ProgressLine(std::string command, int total)
    : command_(std::move(command)),
      total_(total),
      shown_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

ProgressLine::~ProgressLine() { end(); }

void ProgressLine::end() {
  if (!printed_) return;
  std::fputc('\n', stderr);
  std::fflush(stderr);
  printed_ = false;
}

void ProgressLine::step(const std::string& what) {
  const int done = started_++;
  if (!shown_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (total_ > 0) {
    const double left = done > 0 ? elapsed * (total_ - done) / done : 0.0;
    std::fprintf(stderr, "\r%s: step %d of %d (%s), %.0f s elapsed", command_.c_str(), started_, total_, what.c_str(),
                 elapsed);
    if (done > 0) std::fprintf(stderr, ", about %.0f s left", left);
  } else {
    std::fprintf(stderr, "\r%s: step %d (%s), %.0f s elapsed", command_.c_str(), started_, what.c_str(), elapsed);
  }
  std::fputs("\033[K", stderr);  // clear the rest of a longer previous line
  std::fflush(stderr);
  printed_ = true;
}

}  // namespace shatter::cli
