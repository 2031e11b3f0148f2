#include "harness/pipeline/instruction_marks.h"

#include <fmt/core.h>
#include <valgrind/callgrind.h>

#include <string>

namespace shatter::instruction_marks {
namespace {

bool g_enabled = false;
int g_prefracture = 0, g_runtime = 0, g_repetition = 0, g_frame = -1;

}  // namespace

bool running_on_valgrind() { return RUNNING_ON_VALGRIND != 0; }

void enable(bool on) { g_enabled = on; }
bool enabled() { return g_enabled; }

void set_run(int prefracture, int runtime, int repetition) {
  g_prefracture = prefracture;
  g_runtime = runtime;
  g_repetition = repetition;
  g_frame = -1;
}

void set_frame(int frame) { g_frame = frame; }

void begin() {
  if (g_enabled) CALLGRIND_ZERO_STATS;
}

void end(std::string_view stage) {
  if (!g_enabled) return;
  const std::string label =
      fmt::format("shatterbench;{};{};{};{};{}", g_prefracture, g_runtime, g_repetition, g_frame, stage);
  CALLGRIND_DUMP_STATS_AT(label.c_str());
}

}  // namespace shatter::instruction_marks
