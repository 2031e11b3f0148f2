/// libFuzzer target: a binary glTF (.glb) on arbitrary bytes, read by read_asset_bytes (the assimp
/// path read_asset takes for a .glb file, without the file), must return a mesh or a one-line error,
/// never crash, and a returned mesh must satisfy the Mesh invariants (one tag per triangle, every
/// index in range, attributes sized to the triangles, every value finite).

#include "algorithms/assets/read_asset.h"
#include "fuzz/mesh_invariants.h"

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
  // A glTF read through assimp always carries a material per triangle.
  if (mesh->attributes.materials.size() != mesh->triangles.size()) std::abort();
  shatter::fuzz::abort_unless_valid(*mesh);
  return 0;
}
