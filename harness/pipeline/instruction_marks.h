#pragma once
/// Stage boundaries for counting retired instructions under callgrind (the instruction mode of
/// `grid`, docs/compare.md).
///
/// Design note: the kernel of these machines does not expose hardware counters to perf
/// (`perf stat -e instructions` says "not supported"), so instructions are counted by running the grid
/// under valgrind's callgrind, which counts every instruction it executes (deterministic). When marks
/// are on, every StageTimer zeroes callgrind's counters when it starts and dumps them when it ends,
/// labelled `shatterbench;<prefracture>;<runtime>;<repetition>;<frame>;<stage>` (frame -1: setup); the
/// parent process reads the dumps back (callgrind_dumps.h). Off (the default) a mark costs one branch;
/// outside valgrind the client requests are no-ops.

#include <string_view>

namespace shatter::instruction_marks {

/// True when the program runs under valgrind.
bool running_on_valgrind();

/// Turns the marks on or off (off by default).
void enable(bool on);
/// True when the marks are on.
bool enabled();

/// The run the following marks belong to.
void set_run(int prefracture, int runtime, int repetition);
/// The frame the following marks belong to (-1 for the setup).
void set_frame(int frame);

/// Zeroes the counters (a stage starts).
void begin();
/// Dumps the counters since begin() under the current run, frame and `stage`.
void end(std::string_view stage);

}  // namespace shatter::instruction_marks
