#pragma once
/// Shared pieces of the hostile-input battery: scratch folders, file contents, killing a writer.

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace shatter::test {

/// A fresh, empty folder for one test (per process: ctest runs test cases side by side).
inline std::filesystem::path hostile_scratch(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("shatter_hostile_tests_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Writes `bytes` to `p` (plain, not atomic: test input) and returns `p`.
inline std::filesystem::path put_file(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

/// Names in `dir` (not recursive).
inline std::set<std::string> names_in(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

/// Names in `dir` that are temporaries of an atomic write (`.NAME.partial-XXXXXXXX`).
inline int partials_in(const std::filesystem::path& dir) {
  int n = 0;
  for (const std::string& name : names_in(dir)) n += name.find(".partial-") != std::string::npos;
  return n;
}

/// True when process `pid` holds open an unnamed file (O_TMPFILE) of the folder `dir`: the kernel
/// names its link in /proc "DIR/#INODE (deleted)".
inline bool writing_unnamed_file(pid_t pid, const std::filesystem::path& dir) {
  std::error_code ec;
  const std::string prefix = std::filesystem::canonical(dir, ec).string() + "/#";
  for (const auto& e : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    std::error_code link_ec;
    const std::string target = std::filesystem::read_symlink(e.path(), link_ec).string();
    if (!link_ec && target.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

/// Waits up to `limit` for `ready()` to become true, polling every millisecond.
template <class Ready>
bool wait_until(Ready ready, std::chrono::milliseconds limit = std::chrono::milliseconds(60000)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

/// Kills `pid` with SIGKILL and reaps it.
inline void kill_and_reap(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

}  // namespace shatter::test
