#include "harness/results/run_context.h"

#include "harness/results/fnv1a.h"

#include <fmt/core.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <fstream>
#include <thread>

#include <unistd.h>

// Bullet's version macro; the harness target does not put Bullet's folder on the include path, so the
// header is also looked for under /usr/include (it needs only C headers).
#if __has_include(<LinearMath/btScalar.h>)
#include <LinearMath/btScalar.h>
#elif __has_include(<bullet/LinearMath/btScalar.h>)
#include <bullet/LinearMath/btScalar.h>
#endif

#if !defined(SHATTER_GIT_COMMIT) || !defined(SHATTER_BUILD_TYPE) || !defined(SHATTER_CXX_COMPILER) || \
    !defined(SHATTER_CXX_FLAGS) || !defined(SHATTER_CGAL_VERSION) || !defined(SHATTER_EIGEN_VERSION) || \
    !defined(SHATTER_VERSION)
#error "run_context.cpp needs the SHATTER_* build definitions of the harness target (CMakeLists.txt)"
#endif

namespace shatter {

namespace {

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

std::string bullet_version() {
#ifdef BT_BULLET_VERSION
  return fmt::format("{}.{:02}", BT_BULLET_VERSION / 100, BT_BULLET_VERSION % 100);
#else
  return {};
#endif
}

/// "model name" of the first processor; empty where /proc/cpuinfo lacks it (e.g. some ARM kernels).
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');
    if (colon != std::string::npos && trimmed(std::string_view(line).substr(0, colon)) == "model name")
      return trimmed(std::string_view(line).substr(colon + 1));
  }
  return {};
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::array<char, 32> text{};
  std::strftime(text.data(), text.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text.data();
}

std::string host_name() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0) return {};
  return name.data();
}

}  // namespace

std::string context_fingerprint(const RunContext& c) {
  std::uint64_t hash = kFnv1aBasis;
  const auto add = [&hash](std::string_view field) { hash = fnv1a_field(field, hash); };
  for (const std::string* field : {&c.build_type, &c.compiler, &c.flags, &c.cgal_version,
                                   &c.eigen_version, &c.bullet_version, &c.cpu_model})
    add(*field);
  add(std::to_string(c.cores));
  return fmt::format("{:016x}", hash);
}

std::string shatterbench_version() { return SHATTER_VERSION; }

RunContext current_context() {
  RunContext c;
  c.commit = SHATTER_GIT_COMMIT;
  c.build_type = SHATTER_BUILD_TYPE;
  c.compiler = trimmed(SHATTER_CXX_COMPILER);
  c.flags = trimmed(SHATTER_CXX_FLAGS);
  c.cgal_version = SHATTER_CGAL_VERSION;
  c.eigen_version = SHATTER_EIGEN_VERSION;
  c.bullet_version = bullet_version();
  c.cpu_model = cpu_model();
  c.cores = std::thread::hardware_concurrency();
  c.date = utc_now_iso8601();
  c.hostname = host_name();
  c.fingerprint = context_fingerprint(c);
  return c;
}

nlohmann::ordered_json to_json(const RunContext& c) {
  nlohmann::ordered_json j;
  j["commit"] = c.commit;
  j["build_type"] = c.build_type;
  j["compiler"] = c.compiler;
  j["flags"] = c.flags;
  j["cgal_version"] = c.cgal_version;
  j["eigen_version"] = c.eigen_version;
  j["bullet_version"] = c.bullet_version;
  j["cpu_model"] = c.cpu_model;
  j["cores"] = c.cores;
  j["date"] = c.date;
  j["hostname"] = c.hostname;
  j["fingerprint"] = c.fingerprint;
  return j;
}

Result<RunContext> context_from_json(const nlohmann::json& j) {
  if (!j.is_object()) return Error{"context: expected an object"};
  RunContext c;
  const std::pair<const char*, std::string*> strings[] = {
      {"commit", &c.commit},         {"build_type", &c.build_type},
      {"compiler", &c.compiler},     {"flags", &c.flags},
      {"cgal_version", &c.cgal_version}, {"eigen_version", &c.eigen_version},
      {"bullet_version", &c.bullet_version}, {"cpu_model", &c.cpu_model},
      {"date", &c.date},             {"hostname", &c.hostname},
      {"fingerprint", &c.fingerprint}};
  for (const auto& [key, field] : strings) {
    const auto it = j.find(key);
    if (it == j.end()) return Error{fmt::format("context.{}: missing", key)};
    if (!it->is_string()) return Error{fmt::format("context.{}: expected a string", key)};
    *field = it->get<std::string>();
  }
  const auto cores = j.find("cores");
  if (cores == j.end()) return Error{"context.cores: missing"};
  if (!cores->is_number_integer() || cores->get<std::int64_t>() < 0 || cores->get<std::int64_t>() > 1'000'000)
    return Error{"context.cores: expected a whole number from 0 to 1000000"};
  c.cores = cores->get<unsigned>();
  return c;
}

}  // namespace shatter
