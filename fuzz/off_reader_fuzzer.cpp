/// libFuzzer target: read_off on arbitrary bytes must return a mesh or an error, never crash, and a
/// returned mesh must satisfy the Mesh invariant (one tag per triangle, every index in range).

#include "algorithms/core/mesh_io.h"
#include "fuzz/fuzz_input_file.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const shatter::fuzz::InputFile file(data, size);
  shatter::Result<shatter::Mesh> mesh = shatter::read_off(file.path());
  if (!mesh) {
    if (mesh.error().message.empty()) std::abort();
    return 0;
  }
  if (mesh->tags.size() != mesh->triangles.size()) std::abort();
  for (const shatter::Triangle& t : mesh->triangles)
    for (const std::int32_t i : t)
      if (i < 0 || static_cast<std::size_t>(i) >= mesh->vertices.size()) std::abort();
  return 0;
}
