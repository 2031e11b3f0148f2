// The PostgreSQL server of the [postgres] tests (scripts/postgres-test-server, the CTest fixture
// `postgres`): reachable at the URL it wrote, and the version the history store is tested against.
// libpq directly, so that a failure here is the server's, not the store's.

#include "tests/support/postgres_server.h"

#include <catch2/catch.hpp>
#include <libpq-fe.h>

#include <memory>
#include <string>

namespace {

struct ConnectionCloser {
  void operator()(PGconn* conn) const { PQfinish(conn); }
};
struct ResultClearer {
  void operator()(PGresult* result) const { PQclear(result); }
};

}  // namespace

TEST_CASE("postgres test server: the fixture's URL reaches a PostgreSQL 15 server", "[postgres][history]") {
  const std::string url = shatter::test::test_postgres_url();
  const std::unique_ptr<PGconn, ConnectionCloser> conn(PQconnectdb(url.c_str()));
  REQUIRE(conn != nullptr);
  INFO("URL " << url << ": " << PQerrorMessage(conn.get()));
  REQUIRE(PQstatus(conn.get()) == CONNECTION_OK);

  const std::unique_ptr<PGresult, ResultClearer> result(PQexec(conn.get(), "SELECT version()"));
  INFO(PQresultErrorMessage(result.get()));
  REQUIRE(PQresultStatus(result.get()) == PGRES_TUPLES_OK);
  REQUIRE(PQntuples(result.get()) == 1);
  const std::string version = PQgetvalue(result.get(), 0, 0);
  CHECK_THAT(version, Catch::StartsWith("PostgreSQL 15"));
  CHECK(std::string(PQdb(conn.get())) == "shatterbench_test");
}
