#include <catch2/catch.hpp>
#include <vector>

#include "algorithms/core/default_init_allocator.h"
#include "algorithms/core/mesh_attributes.h"

using namespace shatter;

TEST_CASE("default-init allocator: corner values copy, insert, assign and fill as a std::vector does", "[attributes]") {
  const std::vector<double> reference{0.5, -1.25, 3.0, 1e300, -0.0};
  CornerValues values(reference.begin(), reference.end());
  CHECK(std::vector<double>(values.begin(), values.end()) == reference);
  // Growing by resize keeps what was there; what a writer puts in the new room stays.
  values.resize(values.size() + 3);
  for (std::size_t i = reference.size(); i < values.size(); ++i) values[i] = static_cast<double>(i);
  REQUIRE(values.size() == reference.size() + 3);
  for (std::size_t i = 0; i < reference.size(); ++i) CHECK(values[i] == reference[i]);
  CHECK(values.back() == 7.0);
  // A fill still fills; insert, assign and copies carry every value.
  CornerValues filled(4, 2.5);
  CHECK(filled == CornerValues{2.5, 2.5, 2.5, 2.5});
  filled.resize(6, -1.0);
  CHECK(filled == CornerValues{2.5, 2.5, 2.5, 2.5, -1.0, -1.0});
  filled.insert(filled.begin() + 1, reference.begin(), reference.end());
  CHECK(filled.size() == 11);
  CHECK(filled[1] == 0.5);
  CHECK(filled[5] == -0.0);
  const CornerValues copy = filled;
  CHECK(copy == filled);
  CornerValues assigned;
  assigned.assign(reference.begin(), reference.end());
  CHECK(std::vector<double>(assigned.begin(), assigned.end()) == reference);
  CHECK(DefaultInitAllocator<double>() == DefaultInitAllocator<int>());
}
