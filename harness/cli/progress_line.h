#pragma once
/// The progress of a long command as one stderr line rewritten in place ("accuracy: step 3 of 15
/// (elephant, fracture), 12 s elapsed, about 48 s left"), shown only when stderr is a terminal: a
/// log or a CI job gets no carriage returns.

#include <chrono>
#include <string>

namespace shatter::cli {

class ProgressLine {
 public:
  /// `command` names the line; `total` steps (0 when not known: no count and no estimate).
  ProgressLine(std::string command, int total);
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  /// Calls end().
  ~ProgressLine();

  /// Ends the line with a line break when one was shown (before the command prints its results).
  void end();

  /// A step starts: shows "step k of N (what)" with the time so far and the estimate left.
  void step(const std::string& what);

  /// True when the line is shown (stderr is a terminal).
  [[nodiscard]] bool shown() const { return shown_; }

 private:
  std::string command_;
  int total_;
  int started_ = 0;
  bool shown_;
  bool printed_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace shatter::cli
