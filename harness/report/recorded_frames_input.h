#pragma once
/// The recorded frames of a grid results file, for the report's playback (`grid --record-frames`).

#include "algorithms/core/result.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace shatter {

/// The bytes of the sidecar that grid results `j` (read from `file`) name in `recorded_frames.path`,
/// read from the file's own folder as a reference (asset_reference.h: no path leaves it) and checked
/// whole (decode_recorded_frames); "" when the file names none. `used` is the bytes taken so far by
/// the report's recordings and grows by these; past kMaxReportRecordingBytes the file is refused.
Result<std::string> read_grid_recording(const nlohmann::json& j, const std::string& file, std::uint64_t& used);

}  // namespace shatter
