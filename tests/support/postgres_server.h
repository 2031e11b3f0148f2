#pragma once
/// The PostgreSQL server that the tests tagged [postgres] run against.
///
/// scripts/postgres-test-server starts it into SHATTER_POSTGRES_TEST_DIR (build/postgres-test, the
/// CTest fixture `postgres` of CMakeLists.txt), which holds its URL in `url`. The server is required:
/// a test that asks for it when it is not running FAILs, so no [postgres] test passes by checking
/// nothing. It is a throwaway server (trust authentication, fsync off) with one database,
/// `shatterbench_test`, shared by every [postgres] test; CTest runs them one at a time (RESOURCE_LOCK
/// postgres), so a test may leave its tables behind, but must not rely on finding none there.

#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#ifndef SHATTER_POSTGRES_TEST_DIR
#error "tests need SHATTER_POSTGRES_TEST_DIR (a compile definition of the test target)"
#endif

namespace shatter::test {

/// The test server's URL, `postgresql://postgres@127.0.0.1:PORT/shatterbench_test`. FAILs the calling
/// test when the server was not started.
inline std::string test_postgres_url() {
  const std::string file = SHATTER_POSTGRES_TEST_DIR "/url";
  std::ifstream in(file);
  std::string url;
  if (in) std::getline(in, url);
  if (url.empty())
    FAIL("the PostgreSQL test server was not started (no URL in " << file << "): run the tests through "
         << "ctest, whose fixture `postgres` starts it, or start it by hand with "
         << "`scripts/postgres-test-server start " << SHATTER_POSTGRES_TEST_DIR << "`");
  return url;
}

}  // namespace shatter::test
