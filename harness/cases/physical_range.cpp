#include "harness/cases/physical_range.h"

#include <fmt/format.h>

namespace shatter {

bool check_in_range(JsonReader& r, std::string_view path, double value, const PhysicalRange& range) {
  if (r.failed()) return false;
  const bool above = range.max_open ? value >= range.max : value > range.max;
  if (value >= range.min && !above) return true;
  const std::string unit = *range.unit != '\0' ? std::string(" ") + range.unit : std::string();
  r.fail(path, fmt::format("must be in [{:g}, {:g}{}{}, got {:g}", range.min, range.max, range.max_open ? ")" : "]",
                           unit, value));
  return false;
}

bool check_in_range(JsonReader& r, std::string_view path, const Vec3& value, const PhysicalRange& range) {
  for (int i = 0; i < 3; ++i)
    if (!check_in_range(r, index_path(path, static_cast<std::size_t>(i)), value[i], range)) return false;
  return true;
}

}  // namespace shatter
