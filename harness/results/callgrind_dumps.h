#pragma once
/// Reading back the instruction counts that callgrind dumped at the stage marks
/// (harness/pipeline/instruction_marks.h) and attaching them to a grid's samples.

#include "algorithms/core/result.h"
#include "harness/results/grid_record.h"

#include <filesystem>
#include <string>
#include <vector>

namespace shatter {

/// One dump: its label's fields and the instructions (Ir) counted since the previous zeroing.
struct InstructionDump {
  int prefracture = 0;
  int runtime = 0;
  int repetition = 0;
  int frame = -1;          ///< -1: setup
  std::string stage;
  double instructions = 0.0;
};

/// Every dump file in `folder` whose name starts with `prefix` and whose trigger is a shatterbench
/// mark. Errors for unreadable files or a mark without a count.
Result<std::vector<InstructionDump>> read_instruction_dumps(const std::filesystem::path& folder,
                                                            const std::string& prefix);

/// Fills `samples[k].instructions` of every cell of `grid` from `dumps` (per stage, per frame, the
/// first event frame from `event_frame_of`, the largest frame) and sets `grid.metric`. Errors when a
/// dump names a cell, repetition, frame or stage the grid does not have.
Status attach_instructions(GridResult& grid, const std::vector<InstructionDump>& dumps);

}  // namespace shatter
