#pragma once
/// The context block of every result (DESIGN.md section 7: commit, compiler, flags, library versions,
/// CPU, date), and the fingerprint that says whether two results' timings may be compared.
///
/// The fingerprint is FNV-1a (64 bit) over what decides how fast the same code runs, apart from the
/// code itself: build type, compiler, flags, the CGAL, Eigen and Bullet versions, CPU model and core
/// count, each field followed by a 0x1f byte so that fields cannot run into each other. It is written
/// as 16 lower-case hex digits. The commit is left out: comparing two commits on one build setup is
/// what a regression gate does. The date and host name are left out too: two runs on twin machines,
/// or on one machine on two days, are comparable. `compare` refuses results whose fingerprints differ.

#include "algorithms/core/result.h"

#include <nlohmann/json.hpp>

#include <string>

namespace shatter {

/// Where and how a result was measured. Strings are empty when a value is unknown.
struct RunContext {
  std::string commit;          ///< git commit of the sources, abbreviated (12 hex digits)
  std::string build_type;      ///< CMake build type, e.g. "Release"
  std::string compiler;        ///< compiler id and version, e.g. "GNU 12.2.0"
  std::string flags;           ///< C++ compiler flags of the build type, e.g. "-O3 -DNDEBUG"
  std::string cgal_version;    ///< CGAL version, e.g. "5.5.1"
  std::string eigen_version;   ///< Eigen version, e.g. "3.4.0"
  std::string bullet_version;  ///< Bullet version, e.g. "3.24"
  std::string cpu_model;       ///< "model name" of the first processor in /proc/cpuinfo
  unsigned cores = 0;          ///< hardware threads (std::thread::hardware_concurrency; 0 unknown)
  std::string date;            ///< time of the run, UTC ISO 8601, e.g. "2026-11-22T06:31:56Z"
  std::string hostname;        ///< name of the machine
  std::string fingerprint;     ///< context_fingerprint() of the fields above (see the file comment)
};

/// The context of this process: build values compiled in, machine values read now, fingerprint set.
RunContext current_context();

/// The project's version (CMake's project version, e.g. "0.1.0").
std::string shatterbench_version();

/// The fingerprint of `c`: 16 hex digits from the fields that make timings comparable.
std::string context_fingerprint(const RunContext& c);

/// `c` as the JSON `context` object: the fields above under their own names, in declaration order.
nlohmann::ordered_json to_json(const RunContext& c);

/// Reads a `context` object written by to_json(). Every key is required with its type; the error
/// names the key ("context.cores: ..."). The fingerprint is taken as stored, not recomputed.
Result<RunContext> context_from_json(const nlohmann::json& j);

}  // namespace shatter
