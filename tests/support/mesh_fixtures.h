#pragma once
/// Locating and loading the real meshes (CGAL's data/meshes) shared by the tests.
///
/// The folder is `$SHATTER_MESH_DIR` when that is set, else `SHATTER_SOURCE_DIR/data/meshes`
/// (filled by scripts/fetch-meshes). Tests that need a real mesh call have_meshes() first and WARN
/// and return when the folder is missing, so a checkout without the data still passes.

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

/// True when the real-mesh folder exists; otherwise WARNs how to get it.
inline bool have_meshes() {
  std::error_code ec;
  if (std::filesystem::is_directory(mesh_dir(), ec)) return true;
  WARN("real meshes missing: run scripts/fetch-meshes");
  return false;
}

/// Reads and validates `name` (for example "elephant.off") from mesh_dir(); nullopt (with a WARN
/// naming the reason) when the folder or file is missing or the mesh is not a valid solid.
inline std::optional<shatter::Mesh> load_fixture_mesh(std::string name) {
  if (!have_meshes()) return std::nullopt;
  const std::filesystem::path path = mesh_dir() / name;
  Result<Mesh> mesh = read_mesh(path);
  if (!mesh) {
    WARN(mesh.error().message);
    return std::nullopt;
  }
  Result<ValidationReport> report = validate_solid(*mesh, name);
  if (!report) {
    WARN(report.error().message);
    return std::nullopt;
  }
  return std::move(mesh).value();
}

}  // namespace shatter::test
