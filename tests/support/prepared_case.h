#pragma once
/// A built-in case loaded and its solid validated, for tests that run the pipeline or the grid on it.

#include "harness/cases/case_library.h"
#include "harness/pipeline/destruction_run.h"

#include <catch2/catch.hpp>

#include <string>
#include <utility>

namespace shatter::test {

/// The built-in case `name`, prepared; the test fails when it does not load or validate.
inline PreparedCase prepared(const std::string& name) {
  Result<Case> c = find_case(name);
  REQUIRE(c);
  Result<PreparedCase> p = prepare_case(std::move(*c));
  REQUIRE(p);
  return std::move(*p);
}

}  // namespace shatter::test
