#include "algorithms/assets/read_asset.h"

#include "algorithms/assets/assimp_scene_mesh.h"
#include "algorithms/core/mesh_io.h"

#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <mutex>
#include <system_error>

namespace shatter {
namespace {

constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;

/// Lower case, without a leading dot.
std::string normalised_extension(std::string_view extension) {
  if (extension.starts_with('.')) extension.remove_prefix(1);
  std::string ext(extension);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// The first line of an assimp message.
std::string first_line(const char* message) {
  std::string text = message != nullptr ? message : "";
  text = text.substr(0, text.find_first_of("\r\n"));
  return text.empty() ? "assimp could not import the file" : text;
}

/// Keeps the first warning by which assimp says it dropped part of the data (faces whose indices are
/// out of range): assimp imports such a file, but a benchmark must not fracture half of an asset.
class DroppedDataStream : public Assimp::LogStream {
 public:
  void write(const char* message) override {
    const std::string text = message != nullptr ? message : "";
    if (dropped.empty() && (text.find("dropped") != std::string::npos || text.find("out-of-range") != std::string::npos))
      dropped = text;
  }
  std::string dropped;  ///< the warning, without assimp's "Warn, T0: " prefix and newline
};

/// Runs `import` on `importer` with assimp's warnings watched, and converts its scene. assimp's logger
/// is one per process, so imports are serialised while it is watched.
template <class Import>
Result<Mesh> import_scene(Assimp::Importer& importer, const std::string& name, const MeshReadLimits& limits,
                          Import import) {
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  static std::mutex logger_mutex;
  const std::lock_guard lock(logger_mutex);
  const bool own_logger = Assimp::DefaultLogger::isNullLogger();
  if (own_logger) Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
  auto* stream = new DroppedDataStream;  // owned by the logger while attached
  Assimp::DefaultLogger::get()->attachStream(stream, Assimp::Logger::Warn);
  const aiScene* scene = nullptr;
  std::string thrown;
  try {
    scene = import();  // assimp catches its own import errors; this keeps anything else (bad_alloc) here
  } catch (const std::exception& e) {
    thrown = e.what();
  }
  std::string dropped = stream->dropped;
  Assimp::DefaultLogger::get()->detachStream(stream, Assimp::Logger::Warn);
  delete stream;
  if (own_logger) Assimp::DefaultLogger::kill();

  if (!thrown.empty()) return Error{name + ": " + first_line(thrown.c_str())};
  if (scene == nullptr) return Error{name + ": " + first_line(importer.GetErrorString())};
  if (!dropped.empty()) {
    dropped = dropped.substr(dropped.find(':') == std::string::npos ? 0 : dropped.find(':') + 1);
    while (!dropped.empty() && dropped.front() == ' ') dropped.erase(0, 1);
    return Error{name + ": " + first_line(dropped.c_str())};
  }
  return mesh_from_assimp_scene(*scene, name, limits);
}

}  // namespace

bool is_asset_extension(std::string_view extension) {
  const std::string ext = normalised_extension(extension);
  if (ext.empty()) return false;
  if (ext == "off" || ext == "obj") return true;
  return Assimp::Importer().IsExtensionSupported("." + ext);
}

Result<Mesh> read_asset(const std::filesystem::path& path, const MeshReadLimits& limits) {
  const std::string ext = normalised_extension(path.extension().string());
  if (ext == "off" || ext == "obj") return read_mesh(path, limits);
  if (!is_asset_extension(ext))
    return Error{path.string() + ": unknown mesh format '" + path.extension().string() +
                 "' (expected .off, .obj, .gltf, .glb, .fbx, .ply, .stl, .dae, .3ds or another format assimp imports)"};
  // The size limit before assimp reads anything (a .gltf's buffers are read by assimp as it needs them).
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    return Error{path.string() + ": cannot open the mesh file: " + (ec ? ec.message() : "no such file")};
  if (!std::filesystem::is_regular_file(status)) return Error{path.string() + ": cannot read the mesh file: not a regular file"};
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return Error{path.string() + ": cannot read the mesh file: " + ec.message()};
  if (size > limits.max_file_bytes)
    return Error{path.string() + ": larger than the limit of " + std::to_string(limits.max_file_bytes) +
                 " bytes per mesh file (the file has " + std::to_string(size) + " bytes)"};
  Assimp::Importer importer;
  return import_scene(importer, path.string(), limits, [&] { return importer.ReadFile(path.string(), kImportFlags); });
}

Result<Mesh> read_asset_bytes(std::span<const std::uint8_t> bytes, std::string_view extension, const std::string& name,
                              const MeshReadLimits& limits) {
  if (bytes.size() > limits.max_file_bytes)
    return Error{name + ": larger than the limit of " + std::to_string(limits.max_file_bytes) +
                 " bytes per mesh file (the file has " + std::to_string(bytes.size()) + " bytes)"};
  if (bytes.empty()) return Error{name + ": empty file"};
  const std::string hint = normalised_extension(extension);
  Assimp::Importer importer;
  return import_scene(importer, name, limits,
                      [&] { return importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags, hint.c_str()); });
}

}  // namespace shatter
