#pragma once
/// Range checks of the physical quantities of a case file (harness/limits.h, PhysicalRange): the one
/// way the case loader refuses a value that a double holds but the solve and the physics cannot.

#include "harness/cases/json_reader.h"
#include "harness/limits.h"

#include <string_view>

namespace shatter {

/// True when `value` lies in `range`; otherwise records `<path>: must be in [min, max] unit, got v`.
bool check_in_range(JsonReader& r, std::string_view path, double value, const PhysicalRange& range);

/// check_in_range() on each component of `value` (paths `<path>[i]`).
bool check_in_range(JsonReader& r, std::string_view path, const Vec3& value, const PhysicalRange& range);

/// Reads member `key` of `obj` (at `parent`) and checks it against `range`; `out` keeps its default
/// when the key is absent. True when the key was present, read and in range.
template <class T>
bool read_in_range(JsonReader& r, const nlohmann::json& obj, std::string_view parent, std::string_view key, T& out,
                   const PhysicalRange& range) {
  return r.read(obj, parent, key, out) && check_in_range(r, key_path(parent, key), out, range);
}

/// As read_in_range(), but an absent key is an error.
template <class T>
bool read_required_in_range(JsonReader& r, const nlohmann::json& obj, std::string_view parent, std::string_view key,
                            T& out, const PhysicalRange& range) {
  return r.read_required(obj, parent, key, out) && check_in_range(r, key_path(parent, key), out, range);
}

}  // namespace shatter
