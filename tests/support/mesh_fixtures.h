#pragma once
/// Locating and loading the real meshes (CGAL's data/meshes) shared by the tests.
///
/// The folder is `$SHATTER_MESH_DIR` when that is set, else `SHATTER_SOURCE_DIR/data/meshes`
/// (filled by scripts/fetch-meshes, which scripts/build runs). The data is required: a missing folder,
/// a missing file or a mesh that is not a valid solid fails the test that needs it, so scripts/test
/// and CI cannot pass with tests that checked nothing. A local run without the data skips those tests
/// explicitly with `SHATTER_ALLOW_MISSING_MESHES=1` (each one WARNs that it skipped); that skips only a
/// missing folder, never a missing file or an invalid mesh.

#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_validation.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#ifndef SHATTER_SOURCE_DIR
#error "tests need SHATTER_SOURCE_DIR (a compile definition of the test target)"
#endif

namespace shatter::test {

/// The folder holding the real meshes (*.off).
inline std::filesystem::path mesh_dir() {
  if (const char* env = std::getenv("SHATTER_MESH_DIR"); env != nullptr && *env != '\0') return env;
  return std::filesystem::path(SHATTER_SOURCE_DIR) / "data" / "meshes";
}

/// True when SHATTER_ALLOW_MISSING_MESHES is set (to anything but empty or "0"): tests skip, rather
/// than fail, when the real-mesh folder is missing.
inline bool missing_meshes_allowed() {
  const char* env = std::getenv("SHATTER_ALLOW_MISSING_MESHES");
  return env != nullptr && *env != '\0' && std::string(env) != "0";
}

/// True when the real-mesh folder exists. When it is missing the calling test FAILs, or, with
/// SHATTER_ALLOW_MISSING_MESHES, WARNs that it skips and gets false (the test then returns).
inline bool have_meshes() {
  std::error_code ec;
  if (std::filesystem::is_directory(mesh_dir(), ec)) return true;
  if (missing_meshes_allowed()) {
    WARN("skipped: real meshes missing at " << mesh_dir().string() << " (SHATTER_ALLOW_MISSING_MESHES is set)");
    return false;
  }
  FAIL("real meshes missing at " << mesh_dir().string()
                                 << ": run scripts/fetch-meshes, or set SHATTER_ALLOW_MISSING_MESHES=1 to skip "
                                    "the tests that need them");
  return false;
}

/// Reads and validates `name` (for example "elephant.off") from mesh_dir(). A missing folder is as in
/// have_meshes() (nullopt only when skipping is allowed); a missing file or a mesh that is not a valid
/// solid FAILs the calling test with the reader's or the validation's message.
inline std::optional<shatter::Mesh> load_fixture_mesh(std::string name) {
  if (!have_meshes()) return std::nullopt;
  const std::filesystem::path path = mesh_dir() / name;
  Result<Mesh> mesh = read_mesh(path);
  if (!mesh) FAIL("fixture mesh " << name << " unreadable: " << mesh.error().message);
  Result<ValidationReport> report = validate_solid(*mesh, name);
  if (!report) FAIL("fixture mesh " << name << " is not a valid solid: " << report.error().message);
  return std::move(mesh).value();
}

}  // namespace shatter::test
