#include "harness/metrics/fracture_acceptance.h"

#include "algorithms/fracture/fracture_output_check.h"

#include <fmt/core.h>

#include <algorithm>

namespace shatter {

FractureAcceptance acceptance_for(const Fracturer& fracturer) {
  FractureAcceptance acceptance;
  const double stated = limits_with_stated_tolerance(fracturer.volume_tolerance()).max_volume_error;
  acceptance.max_volume_error = stated;
  // A surface within a voxel of the input's misplaces the sample points in that shell, a share of the
  // same order as the volume error.
  acceptance.max_partition_error = std::max(acceptance.max_partition_error, stated);
  return acceptance;
}

std::vector<std::string> failed_fracture_checks(const FractureMetrics& m, const FractureAcceptance& acceptance) {
  std::vector<std::string> failed;
  if (m.fragment_count < 1) failed.emplace_back("fragments: no fragment");
  if (!m.all_closed) failed.push_back("all_closed: " + (m.fragment_problem.empty() ? std::string("false") : m.fragment_problem));
  // Negated comparisons: a NaN figure fails too.
  if (!(m.volume_error <= acceptance.max_volume_error))
    failed.push_back(fmt::format("volume_error {:.6g} > {:g}", m.volume_error, acceptance.max_volume_error));
  if (!(m.partition_error <= acceptance.max_partition_error))
    failed.push_back(fmt::format("partition_error {:.6g} > {:g} ({} samples)", m.partition_error,
                                 acceptance.max_partition_error, m.partition_samples));
  return failed;
}

std::vector<std::string> failed_attribute_checks(const AttributeMetrics& a, const FractureAcceptance& acceptance) {
  std::vector<std::string> failed;
  if (!a.measured) return failed;
  const double limit = acceptance.max_attribute_error;
  if (!(a.uv_error <= limit)) failed.push_back(fmt::format("uv_error {:.6g} > {:g}", a.uv_error, limit));
  if (!(a.normal_error <= limit)) failed.push_back(fmt::format("normal_error {:.6g} > {:g}", a.normal_error, limit));
  if (!(a.cap_normal_error <= limit))
    failed.push_back(fmt::format("cap_normal_error {:.6g} > {:g}", a.cap_normal_error, limit));
  if (a.material_errors > 0) failed.push_back(fmt::format("material_errors: {} faces", a.material_errors));
  return failed;
}

}  // namespace shatter
