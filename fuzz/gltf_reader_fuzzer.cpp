/// libFuzzer target: a binary glTF (.glb) on arbitrary bytes, read by read_asset_bytes (the assimp
/// path read_asset takes for a .glb file, without the file), must return a mesh or a one-line error,
/// never crash, and a returned mesh must satisfy the Mesh invariants (one tag per triangle, every
/// index in range, attributes sized to the triangles, every value finite).

#include "algorithms/assets/read_asset.h"

#include <cmath>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  shatter::MeshReadLimits limits;
  limits.max_vertices = 1'000'000;  // keeps a hostile count a quick error, not a slow input
  limits.max_triangles = 1'000'000;
  shatter::Result<shatter::Mesh> mesh = shatter::read_asset_bytes(std::span(data, size), "glb", "fuzz.glb", limits);
  if (!mesh) {
    const std::string& message = mesh.error().message;
    if (message.empty() || message.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  if (mesh->tags.size() != mesh->triangles.size()) std::abort();
  for (const shatter::Triangle& t : mesh->triangles)
    for (const std::int32_t i : t)
      if (i < 0 || static_cast<std::size_t>(i) >= mesh->vertices.size()) std::abort();
  for (const shatter::Vec3& p : mesh->vertices)
    if (!p.allFinite()) std::abort();
  const shatter::MeshAttributes& a = mesh->attributes;
  if (a.corners.size() != 3 * mesh->triangles.size() * static_cast<std::size_t>(a.layout.stride())) std::abort();
  if (a.materials.size() != mesh->triangles.size()) std::abort();
  for (const std::int32_t m : a.materials)
    if (m < 0 || static_cast<std::size_t>(m) >= a.slots.size()) std::abort();
  for (const double v : a.corners)
    if (!std::isfinite(v)) std::abort();
  return 0;
}
