#include "harness/results/callgrind_dumps.h"

#include "algorithms/core/bounded_read.h"
#include "algorithms/core/mesh_text.h"
#include "harness/limits.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string_view>

namespace shatter {
namespace {

constexpr std::string_view kTrigger = "desc: Trigger: Client Request: ";

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, sep)) out.push_back(item);
  return out;
}

}  // namespace

Result<std::vector<InstructionDump>> read_instruction_dumps(const std::filesystem::path& folder,
                                                            const std::string& prefix) {
  std::vector<InstructionDump> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const Result<std::string> text = read_file_bounded(entry.path(), kMaxResultsFileBytes, "instruction dump");
    if (!text) return text.error();
    std::string label;
    double count = -1.0;
    for (std::string_view rest = *text; !rest.empty();) {  // "\n", "\r\n" and "\r" end a line
      const std::size_t end = rest.find_first_of("\r\n");
      const std::string_view line = rest.substr(0, end);
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
      if (line.starts_with(kTrigger)) label = std::string(line.substr(kTrigger.size()));
      if (line.starts_with("totals: ") || line.starts_with("summary: ")) {
        std::string_view number = line.substr(line.find(' ') + 1);
        number = number.substr(0, number.find(' '));
        const Result<double> x = parse_finite_double(number);
        if (!x || *x < 0.0) return Error{entry.path().string() + ": malformed instruction count"};
        count = *x;
      }
    }
    if (label.rfind("shatterbench;", 0) != 0) continue;  // e.g. the final dump at exit
    if (count < 0.0) return Error{entry.path().string() + ": a mark without an instruction count"};
    const std::vector<std::string> f = split(label, ';');
    if (f.size() != 6) return Error{entry.path().string() + ": malformed mark \"" + label + "\""};
    int numbers[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      const Result<std::int64_t> n = parse_integer(f[static_cast<std::size_t>(i + 1)]);
      const std::int64_t lowest = i == 3 ? -1 : 0;  // frame -1: work before the first frame (setup)
      if (!n || *n < lowest || *n > std::numeric_limits<int>::max())
        return Error{entry.path().string() + ": malformed mark \"" + label + "\""};
      numbers[i] = static_cast<int>(*n);
    }
    InstructionDump d;
    d.prefracture = numbers[0];
    d.runtime = numbers[1];
    d.repetition = numbers[2];
    d.frame = numbers[3];
    d.stage = f[5];
    d.instructions = count;
    out.push_back(std::move(d));
  }
  if (ec) return Error{folder.string() + ": " + ec.message()};
  return out;
}

Status attach_instructions(GridResult& grid, const std::vector<InstructionDump>& dumps) {
  const auto stage_index = [](const std::string& name) -> int {
    for (const Stage s : kAllStages)
      if (stage_name(s) == name) return static_cast<int>(s);
    return -1;
  };
  for (GridCell& c : grid.cells)
    for (GridSample& s : c.samples) {
      s.instructions = InstructionCounts{};
      s.instructions->frames.assign(s.frame_ms.size(), 0.0);
    }
  for (const InstructionDump& d : dumps) {
    auto cell = std::find_if(grid.cells.begin(), grid.cells.end(), [&](const GridCell& c) {
      return c.prefracture == d.prefracture && c.runtime == d.runtime;
    });
    if (cell == grid.cells.end() || d.repetition < 0 || d.repetition >= static_cast<int>(cell->samples.size()))
      return Error{fmt::format("instruction mark for cell {} x {} repetition {} not in the grid", d.prefracture,
                               d.runtime, d.repetition)};
    InstructionCounts& counts = *cell->samples[static_cast<std::size_t>(d.repetition)].instructions;
    const int stage = stage_index(d.stage);
    if (stage < 0) return Error{"instruction mark for an unknown stage \"" + d.stage + "\""};
    if (d.frame < 0) {
      counts.setup[static_cast<std::size_t>(stage)] += d.instructions;
      continue;
    }
    if (d.frame >= static_cast<int>(counts.frames.size()))
      return Error{fmt::format("instruction mark for frame {} beyond the run's {} frames", d.frame, counts.frames.size())};
    counts.stages[static_cast<std::size_t>(stage)] += d.instructions;
    counts.frames[static_cast<std::size_t>(d.frame)] += d.instructions;
  }
  for (GridCell& c : grid.cells)
    for (GridSample& s : c.samples) {
      InstructionCounts& counts = *s.instructions;
      counts.worst_frame = counts.frames.empty() ? 0.0 : *std::max_element(counts.frames.begin(), counts.frames.end());
      if (s.event_frame >= 0 && s.event_frame < static_cast<int>(counts.frames.size()))
        counts.event = counts.frames[static_cast<std::size_t>(s.event_frame)];
    }
  grid.metric = "instructions";
  return {};
}

}  // namespace shatter
