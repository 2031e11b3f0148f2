#include "harness/stability/hazard_outcome.h"

namespace shatter {

HazardOutcome refusal_outcome(const Error& error) {
  return error.cause == ErrorCause::algorithm_fault ? HazardOutcome::invalid_output : HazardOutcome::rejected_input;
}

std::string_view outcome_tag(HazardOutcome outcome) {
  switch (outcome) {
    case HazardOutcome::valid: return "VALID";
    case HazardOutcome::invalid_output: return "INVALID_OUTPUT";
    case HazardOutcome::rejected_input: return "REJECTED_INPUT";
    case HazardOutcome::refused_valid_input: return "REFUSED_VALID_INPUT";
    case HazardOutcome::crash: return "CRASH";
    case HazardOutcome::timeout: return "TIMEOUT";
  }
  return "CRASH";
}

nlohmann::ordered_json to_json(const HazardResult& r) {
  nlohmann::ordered_json j = {
      {"hazard", r.hazard},           {"algorithm", r.algorithm}, {"kind", r.kind},
      {"outcome", outcome_tag(r.outcome)}, {"detail", r.detail},  {"worst_error", r.worst_error},
      {"fragments", r.fragments},     {"time_ms", r.time_ms},
  };
  if (r.kind == "stress") {
    j["converged"] = r.converged;
    j["residual"] = r.residual;
    j["iterations"] = r.iterations;
  }
  return j;
}

bool from_json(const nlohmann::json& j, HazardResult& r) {
  try {
    r.hazard = j.at("hazard").get<std::string>();
    r.algorithm = j.at("algorithm").get<std::string>();
    r.kind = j.at("kind").get<std::string>();
    const std::string tag = j.at("outcome").get<std::string>();
    bool known = false;
    for (HazardOutcome o : {HazardOutcome::valid, HazardOutcome::invalid_output, HazardOutcome::rejected_input,
                            HazardOutcome::refused_valid_input, HazardOutcome::crash, HazardOutcome::timeout})
      if (outcome_tag(o) == tag) {
        r.outcome = o;
        known = true;
      }
    if (!known) return false;
    r.detail = j.at("detail").get<std::string>();
    r.worst_error = j.at("worst_error").get<double>();
    r.fragments = j.at("fragments").get<int>();
    r.time_ms = j.at("time_ms").get<double>();
    if (j.contains("converged")) {
      r.converged = j.at("converged").get<bool>();
      r.residual = j.at("residual").get<double>();
      r.iterations = j.at("iterations").get<int>();
    }
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

}  // namespace shatter
