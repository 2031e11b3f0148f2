#include "harness/report/recorded_frames_input.h"

#include "algorithms/core/asset_reference.h"
#include "algorithms/core/bounded_read.h"
#include "harness/limits.h"
#include "harness/results/recorded_frames.h"

#include <fmt/core.h>

#include <filesystem>

namespace shatter {

Result<std::string> read_grid_recording(const nlohmann::json& j, const std::string& file, std::uint64_t& used) {
  const auto block = j.find("recorded_frames");
  if (block == j.end()) return std::string();
  if (!block->is_object() || !block->contains("path") || !(*block)["path"].is_string())
    return Error{file + ": recorded_frames.path: expected a string"};
  const std::string name = (*block)["path"].get<std::string>();
  const std::filesystem::path folder = std::filesystem::path(file).parent_path();
  const std::uint64_t room = used < kMaxReportRecordingBytes ? kMaxReportRecordingBytes - used : 0;
  Result<std::filesystem::path> sidecar =
      resolve_reference(folder.empty() ? std::filesystem::path(".") : folder, name, kMaxResultsFileBytes, file + ": recorded_frames.path");
  if (!sidecar) return sidecar.error();
  // The limit is checked on the size before anything is read (resolve_reference found a regular file).
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(*sidecar, ec);
  if (!ec && size > room)
    return Error{fmt::format("{}: {} bytes of recorded frames, past the report's limit of {} bytes for playback "
                             "(docs/report.md, Limits): record fewer cells or frames",
                             sidecar->string(), size, kMaxReportRecordingBytes)};
  Result<std::string> bytes = read_file_bounded(*sidecar, room, "recorded frames");
  if (!bytes) return bytes.error();
  if (Result<std::vector<RecordedFrames>> decoded = decode_recorded_frames(*bytes, sidecar->string()); !decoded)
    return decoded.error();
  used += bytes->size();
  return std::move(*bytes);
}

}  // namespace shatter
