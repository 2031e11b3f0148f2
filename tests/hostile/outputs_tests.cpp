// Hostile input, outputs: every file and folder a command writes goes through harness/output/, which
// never destroys what shatterbench did not write, never leaves a partial output, refuses targets that
// are not regular files or that two outputs share, and serialises concurrent writers.

#include "harness/output/atomic_file.h"
#include "harness/output/output_folder.h"
#include "harness/output/output_targets.h"
#include "tests/hostile/hostile_support.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

/// A filler that writes `count` files named `piece_NNN.txt`, each holding `tag`.
FolderFiller pieces(int count, const std::string& tag) {
  return [count, tag](const fs::path& staging) -> Status {
    for (int i = 0; i < count; ++i)
      if (Status s = write_file_atomically(staging / ("piece_" + std::to_string(i) + ".txt"), tag); !s) return s;
    return {};
  };
}

}  // namespace

TEST_CASE("outputs: a folder that shatterbench did not write is never replaced or emptied", "[hostile][outputs]") {
  const fs::path dir = hostile_scratch("foreign_folder");
  const fs::path user = dir / "user";
  fs::create_directories(user / "sub");
  put_file(user / "thesis.tex", "years of work");
  put_file(user / "sub" / "data.csv", "1,2,3");
  for (const fs::path& target : {user, user / "sub"}) {
    const Status s = write_folder_atomically(target, pieces(3, "new"));
    REQUIRE_FALSE(s.ok());
    CHECK_THAT(s.error().message, Catch::Contains("did not write"));
    CHECK_FALSE(check_outputs({{"--out", target, true}}).ok());
  }
  CHECK(file_bytes(user / "thesis.tex") == "years of work");
  CHECK(file_bytes(user / "sub" / "data.csv") == "1,2,3");
  CHECK(partials_in(dir) == 0);
  CHECK(partials_in(user) == 0);

  // A regular file where a folder output should go is refused too, and kept.
  put_file(dir / "notes", "keep");
  CHECK_FALSE(write_folder_atomically(dir / "notes", pieces(1, "x")).ok());
  CHECK(file_bytes(dir / "notes") == "keep");
}

TEST_CASE("outputs: an absent, empty or own folder is written whole and replaced whole", "[hostile][outputs]") {
  const fs::path dir = hostile_scratch("own_folder");
  const fs::path out = dir / "out";
  REQUIRE(write_folder_atomically(out, pieces(5, "first")).ok());
  CHECK(fs::exists(out / kOutputMarker));
  CHECK(file_bytes(out / "piece_4.txt") == "first");
  // The second run writes fewer files: none of the first run's stays.
  REQUIRE(write_folder_atomically(out, pieces(2, "second")).ok());
  CHECK(names_in(out) == std::set<std::string>{std::string(kOutputMarker), "piece_0.txt", "piece_1.txt"});
  CHECK(file_bytes(out / "piece_1.txt") == "second");
  fs::create_directory(dir / "empty");
  REQUIRE(write_folder_atomically(dir / "empty", pieces(1, "e")).ok());
  CHECK(file_bytes(dir / "empty" / "piece_0.txt") == "e");
  CHECK(partials_in(dir) == 0);

  // A failing filler leaves the old folder as it was and nothing beside it.
  const Status failed = write_folder_atomically(out, [](const fs::path& staging) -> Status {
    put_file(staging / "half", "half");
    return Error{"the fill failed"};
  });
  CHECK_FALSE(failed.ok());
  CHECK(file_bytes(out / "piece_1.txt") == "second");
  CHECK_FALSE(fs::exists(out / "half"));
  CHECK(partials_in(dir) == 0);
}

TEST_CASE("outputs: a target that is not a regular file is refused and left alone", "[hostile][outputs]") {
  const fs::path dir = hostile_scratch("not_regular");
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0644) == 0);
  fs::create_directory(dir / "folder");
  put_file(dir / "folder" / "inner", "inner");
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  REQUIRE(sock >= 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = (dir / "socket").string();
  REQUIRE(socket_path.size() < sizeof address.sun_path);
  std::copy(socket_path.begin(), socket_path.end(), address.sun_path);
  REQUIRE(::bind(sock, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
  const std::vector<fs::path> targets = {dir / "fifo", dir / "folder", dir / "socket", "/dev/null", "/dev/zero"};
  for (const fs::path& target : targets) {
    INFO(target);
    const Status checked = check_outputs({{"--json", target}});
    REQUIRE_FALSE(checked.ok());
    CHECK_THAT(checked.error().message, Catch::Contains("not a regular file"));
    if (target.parent_path() == dir) CHECK_FALSE(write_file_atomically(target, "x").ok());
  }
  ::close(sock);
  struct stat st {};
  REQUIRE(::stat((dir / "fifo").c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  REQUIRE(::lstat((dir / "socket").c_str(), &st) == 0);
  CHECK(S_ISSOCK(st.st_mode));
  CHECK(file_bytes(dir / "folder" / "inner") == "inner");
  CHECK(partials_in(dir) == 0);
}

TEST_CASE("outputs: two outputs that resolve to one file are refused", "[hostile][outputs]") {
  const fs::path dir = hostile_scratch("same_file");
  fs::create_directory(dir / "sub");
  put_file(dir / "a.json", "");  // empty: a file nothing is lost in, so only the sameness is judged
  fs::create_symlink(dir / "a.json", dir / "link.json");
  fs::create_hard_link(dir / "a.json", dir / "hard.json");
  const std::vector<std::pair<fs::path, fs::path>> pairs = {
      {dir / "a.json", dir / "a.json"},
      {dir / "a.json", dir / "sub" / ".." / "a.json"},
      {dir / "a.json", dir / "link.json"},
      {dir / "a.json", dir / "hard.json"},
      {dir / "new.json", dir / "." / "new.json"},
  };
  for (const auto& [a, b] : pairs) {
    INFO(a << " and " << b);
    const Status s = check_outputs({{"--json", a}, {"--junit", b}});
    REQUIRE_FALSE(s.ok());
    CHECK_THAT(s.error().message, Catch::Contains("--json") && Catch::Contains("--junit"));
  }
  CHECK_FALSE(check_outputs({{"--out", dir / "rep", true}, {"--json", dir / "rep" / "x.json"}}).ok());
  CHECK(check_outputs({{"--json", dir / "a.json"}, {"--junit", dir / "b.xml"}}).ok());
}

TEST_CASE("outputs: kill -9 during a file write leaves the old file and nothing beside it",
          "[hostile][outputs][kill]") {
  const fs::path dir = hostile_scratch("kill_file");
  const fs::path target = dir / "grid.json";
  put_file(target, "old results");
  for (int trial = 0; trial < 3; ++trial) {
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      const std::string big(std::size_t(256) << 20, 'n');  // 256 MiB: the write takes long enough to be caught
      (void)write_file_atomically(target, big);
      ::_exit(0);
    }
    // The write is in progress once the child holds an unnamed file of the folder open.
    const bool caught = wait_until([&] { return writing_unnamed_file(pid, dir); });
    kill_and_reap(pid);
    REQUIRE(caught);
    CHECK(file_bytes(target) == "old results");  // never a partial file at the target
    CHECK(names_in(dir) == std::set<std::string>{"grid.json"});
    REQUIRE(write_file_atomically(target, "new results").ok());
    CHECK(partials_in(dir) == 0);
    CHECK(file_bytes(target) == "new results");
    put_file(target, "old results");
  }
}

TEST_CASE("outputs: a user's file or folder named like a temporary is never removed", "[hostile][outputs]") {
  const fs::path dir = hostile_scratch("lookalike");
  const fs::path file_twin = put_file(dir / ".grid.json.partial-0123abcd", "my notes");
  const fs::path folder_twin = dir / ".out.partial-89abcdef";
  fs::create_directories(folder_twin);
  put_file(folder_twin / "thesis.txt", "chapter 1");
  REQUIRE(write_file_atomically(dir / "grid.json", "results").ok());
  REQUIRE(write_folder_atomically(dir / "out", pieces(2, "new")).ok());
  CHECK(file_bytes(file_twin) == "my notes");
  CHECK(file_bytes(folder_twin / "thesis.txt") == "chapter 1");
  CHECK(file_bytes(dir / "grid.json") == "results");
}

TEST_CASE("outputs: kill -9 during a folder write leaves the old folder, the next write removes the staging",
          "[hostile][outputs][kill]") {
  const fs::path dir = hostile_scratch("kill_folder");
  const fs::path out = dir / "fragments";
  REQUIRE(write_folder_atomically(out, pieces(4, "old")).ok());
  const std::set<std::string> old_names = names_in(out);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    (void)write_folder_atomically(out, pieces(1000000, "new"));
    ::_exit(0);
  }
  const bool caught = wait_until([&] {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(".partial-") != std::string::npos &&
          fs::exists(e.path() / "piece_100.txt"))
        return true;
    return false;
  });
  kill_and_reap(pid);
  REQUIRE(caught);
  CHECK(names_in(out) == old_names);
  CHECK(file_bytes(out / "piece_3.txt") == "old");
  CHECK(partials_in(dir) == 1);
  REQUIRE(write_folder_atomically(out, pieces(2, "new")).ok());
  CHECK(partials_in(dir) == 0);
  CHECK(file_bytes(out / "piece_1.txt") == "new");
}

TEST_CASE("outputs: concurrent writers of one output set leave a set from one writer", "[hostile][outputs]") {
  const fs::path dir = hostile_scratch("concurrent");
  const fs::path json = dir / "grid.json";
  const fs::path csv = dir / "grid.csv";
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<pid_t> writers;
    for (const char tag : {'a', 'b'}) {
      const pid_t pid = ::fork();
      REQUIRE(pid >= 0);
      if (pid == 0) {
        const std::string big(std::size_t(8) << 20, tag);  // 8 MiB: long enough for the writers to overlap
        const std::string small(1, tag);
        for (int k = 0; k < 3; ++k) {
          const FileContent set[] = {{json, big}, {csv, small}};
          if (!write_files_atomically(set).ok()) ::_exit(1);
        }
        ::_exit(0);
      }
      writers.push_back(pid);
    }
    for (const pid_t pid : writers) {
      int status = 0;
      ::waitpid(pid, &status, 0);
      REQUIRE(WIFEXITED(status));
      REQUIRE(WEXITSTATUS(status) == 0);
    }
    const std::string j = file_bytes(json);
    const std::string c = file_bytes(csv);
    REQUIRE(j.size() == std::size_t(8) << 20);
    REQUIRE(c.size() == 1);
    CHECK(j.front() == c.front());
    CHECK(j.back() == c.front());
    CHECK(partials_in(dir) == 0);
  }
}
