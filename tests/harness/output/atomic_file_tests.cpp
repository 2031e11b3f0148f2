// Atomic file writes: the content arrives whole, replaces an old file, and a failure leaves nothing.

#include "harness/output/atomic_file.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

/// A fresh, empty folder for this test's files.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "shatter_results_tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Names of everything in `dir`.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("atomic file: writes the content and leaves no temporary", "[results]") {
  const fs::path dir = scratch("write");
  const std::string content = std::string("{\"a\": 1}\n") + std::string(1, '\0') + "binary";
  const Status s = write_file_atomically(dir / "out.json", content);
  REQUIRE(s.ok());
  CHECK(read_all(dir / "out.json") == content);
  CHECK(entries(dir) == std::vector<std::string>{"out.json"});
}

TEST_CASE("atomic file: replaces an existing file", "[results]") {
  const fs::path dir = scratch("replace");
  { std::ofstream(dir / "out.json") << "an older and much longer content than the new one\n"; }
  REQUIRE(write_file_atomically(dir / "out.json", "new").ok());
  CHECK(read_all(dir / "out.json") == "new");
  CHECK(entries(dir) == std::vector<std::string>{"out.json"});
}

TEST_CASE("atomic file: an empty content gives an empty file", "[results]") {
  const fs::path dir = scratch("empty");
  REQUIRE(write_file_atomically(dir / "out.json", "").ok());
  CHECK(fs::exists(dir / "out.json"));
  CHECK(fs::file_size(dir / "out.json") == 0);
}

TEST_CASE("atomic file: a missing folder is an error naming the path", "[results]") {
  const fs::path dir = scratch("missing");
  const fs::path target = dir / "no_such_folder" / "out.json";
  const Status s = write_file_atomically(target, "x");
  REQUIRE_FALSE(s.ok());
  CHECK_THAT(s.error().message, Catch::Contains(target.string()));
  CHECK_FALSE(fs::exists(target));
  CHECK_FALSE(fs::exists(target.parent_path()));
  CHECK(entries(dir).empty());
}

TEST_CASE("atomic file: a folder in the way is an error and is left alone", "[results]") {
  const fs::path dir = scratch("folder_in_the_way");
  fs::create_directories(dir / "out.json" / "inner");
  const Status s = write_file_atomically(dir / "out.json", "x");
  REQUIRE_FALSE(s.ok());
  CHECK_THAT(s.error().message, Catch::Contains((dir / "out.json").string()));
  CHECK(fs::is_directory(dir / "out.json" / "inner"));
  CHECK(entries(dir) == std::vector<std::string>{"out.json"});
}
