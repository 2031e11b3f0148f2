/// libFuzzer target: an asset file of arbitrary bytes, imported by read_asset_isolated (assimp in a
/// child process under its memory and time limits, harness/cases/isolated_import.h). The first byte
/// picks the format (its extension), the rest is the file. Whatever assimp does in the child (a crash,
/// an abort, a limit reached), the parent must get a mesh that satisfies the Mesh invariants or a
/// one-line error, and never crash itself.

#include "fuzz/mesh_invariants.h"
#include "harness/cases/isolated_import.h"

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

/// The folder of the input files (one file per fuzzer process, removed after each input): assimp
/// picks its importer by the extension, so the input cannot be a memfd. libFuzzer ends with _Exit,
/// so the folder is shared and stays, empty.
const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() / "shatter_import_fuzz";
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static constexpr std::array<const char*, 8> kExtensions = {"ply", "gltf", "glb", "dae", "3mf", "stl", "fbx", "3ds"};
  if (size < 1) return 0;
  const std::filesystem::path file = scratch() / (std::to_string(::getpid()) + "." + kExtensions[data[0] % kExtensions.size()]);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  shatter::MeshReadLimits limits;
  limits.max_vertices = 1'000'000;
  limits.max_triangles = 1'000'000;
  shatter::ImportLimits import;
  import.time_s = 2.0;  // a quick end to an input that makes assimp spin (libFuzzer's -timeout is 10 s)
  shatter::Result<shatter::Mesh> mesh = shatter::read_asset_isolated(file, limits, import);
  std::error_code ec;
  std::filesystem::remove(file, ec);
  if (!mesh) {
    const std::string& message = mesh.error().message;
    if (message.empty() || message.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  shatter::fuzz::abort_unless_valid(*mesh);
  return 0;
}
