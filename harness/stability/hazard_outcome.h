#pragma once
/// The verdict of one hazard case on one algorithm (docs/stability.md): one outcome tag, the failed
/// check or the refusal message, and the worst error figure.

#include "algorithms/core/result.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace shatter {

/// How a hazard case ended, after CGAL's robustness benchmark tags.
enum class HazardOutcome {
  valid,           ///< every check passed
  invalid_output,  ///< the algorithm returned output that failed a check (named in `detail`)
  rejected_input,  ///< the algorithm or the input validation refused the input with an error message
  /// the algorithm refused an input that every fracturer must take (a valid solid, an ordinary
  /// request): a failure, like invalid output
  refused_valid_input,
  crash,           ///< the isolated run died (signal, abort, sanitizer) or exited without a verdict
  timeout,         ///< the isolated run passed its time limit and was killed
};

/// The outcome of an algorithm's error: rejected_input for a refusal, invalid_output for a fault the
/// host caught (an exception, a null, a result that failed the output checks; ErrorCause).
HazardOutcome refusal_outcome(const Error& error);

/// "VALID", "INVALID_OUTPUT", "REJECTED_INPUT", "REFUSED_VALID_INPUT", "CRASH" or "TIMEOUT".
std::string_view outcome_tag(HazardOutcome outcome);

/// One row of the stability report.
struct HazardResult {
  std::string hazard;           ///< hazard case name, e.g. "cut-through-vertices"
  std::string algorithm;        ///< fracturer or stress model name
  std::string kind;             ///< "fracture" or "stress"
  HazardOutcome outcome = HazardOutcome::crash;
  std::string detail;           ///< failed check, refusal message or signal; empty when valid
  double worst_error = 0.0;     ///< largest relative error figure (volume, partition or residual); dimensionless
  int fragments = 0;            ///< fragments produced (fracture) or nodes (stress)
  double time_ms = 0.0;         ///< wall time of the isolated run, ms
  bool converged = true;        ///< stress: every solve reached its tolerance
  double residual = 0.0;        ///< stress: largest relative residual |K u - f| / |f|
  int iterations = 0;           ///< stress: iterative-solver iterations, summed
};

/// The result as a JSON object (keys as the fields; `outcome` holds the tag).
nlohmann::ordered_json to_json(const HazardResult& result);
/// Reads what to_json wrote; false when a key is missing or of the wrong type.
bool from_json(const nlohmann::json& json, HazardResult& result);

}  // namespace shatter
