#pragma once
/// The text of a results JSON: nlohmann's `dump(1)` layout (one value a line, one space of indent per
/// level), except that the per-frame arrays of numbers that would make the file long (each stage's
/// times in every frame, `frame_stages_ms`) are written on one line.
///
/// Design note: a file without those arrays is byte for byte `dump(1)`, so results files keep their
/// layout; a 300-frame array on one line costs its numbers and a separator each, not an indent and a
/// line break per value (docs/results.md says what it measures).

#include <nlohmann/json.hpp>

#include <string>

namespace shatter {

/// `j` as `j.dump(1)` would write it, but every array of numbers that is a member of an object named
/// `frame_stages_ms` on one line, `[0.25, 0, 1.5]`. Throws as dump does on a string that is not UTF-8.
[[nodiscard]] std::string results_json_text(const nlohmann::ordered_json& j);

}  // namespace shatter
