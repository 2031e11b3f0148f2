#include "algorithms/assets/read_asset.h"

#include "algorithms/assets/confined_io_system.h"

#include "algorithms/assets/assimp_scene_mesh.h"
#include "algorithms/core/bounded_read.h"
#include "algorithms/core/mesh_io.h"

#include <assimp/BaseImporter.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <exception>
#include <mutex>
#include <set>
#include <system_error>
#include <vector>

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

/// Why `bytes` is not a well-formed binary glTF container (an empty string when it is one): the
/// 12-byte header (magic "glTF", version 2, a length no larger than the data) and each chunk's
/// length within the data. assimp allocates what a chunk header claims before it checks, so a
/// 1.5 KB file claiming a 200 MB chunk costs seconds there; here it is refused at once.
std::string glb_container_problem(std::span<const std::uint8_t> bytes) {
  const auto u32 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(bytes[at]) | static_cast<std::uint32_t>(bytes[at + 1]) << 8 |
           static_cast<std::uint32_t>(bytes[at + 2]) << 16 | static_cast<std::uint32_t>(bytes[at + 3]) << 24;
  };
  if (bytes.size() < 20) return "shorter than a binary glTF header";
  if (u32(0) != 0x46546C67u) return "no binary glTF magic 'glTF'";
  if (u32(4) != 2) return "binary glTF version " + std::to_string(u32(4)) + " (only 2 is read)";
  if (u32(8) > bytes.size())
    return "the header's length " + std::to_string(u32(8)) + " is past the end of the data (" + std::to_string(bytes.size()) + " bytes)";
  const std::size_t end = u32(8);
  if (end < 20) return "the header's length " + std::to_string(end) + " leaves no room for the JSON chunk";
  for (std::size_t at = 12, chunk = 0; at < end; ++chunk) {
    if (end - at < 8) return "chunk " + std::to_string(chunk) + " is cut short";
    const std::uint32_t length = u32(at);
    if (length > end - at - 8) return "chunk " + std::to_string(chunk) + "'s length " + std::to_string(length) + " is past the end";
    if (chunk == 0 && u32(at + 4) != 0x4E4F534Au) return "the first chunk is not JSON";
    at += 8 + length;
  }
  return {};
}

/// The JSON text of a binary glTF container that glb_container_problem accepted.
std::string_view glb_json(std::span<const std::uint8_t> bytes) {
  const std::uint32_t length = static_cast<std::uint32_t>(bytes[12]) | static_cast<std::uint32_t>(bytes[13]) << 8 |
                               static_cast<std::uint32_t>(bytes[14]) << 16 | static_cast<std::uint32_t>(bytes[15]) << 24;
  return {reinterpret_cast<const char*>(bytes.data()) + 20, length};
}

/// A non-negative integer member of a glTF object, `fallback` when absent, -1 when not one.
std::int64_t member(const nlohmann::json& object, const char* key, std::int64_t fallback) {
  if (!object.contains(key)) return fallback;
  const nlohmann::json& v = object[key];
  return v.is_number_unsigned() ? static_cast<std::int64_t>(std::min<std::uint64_t>(v.get<std::uint64_t>(), 1ULL << 40)) : -1;
}

/// Why the accessors or buffer views of `doc` reach outside their data (empty when none does): the
/// glTF specification's bounds, which assimp 5.2 does not check before it copies (an accessor whose
/// last element ends past its buffer view is read past the end of the buffer).
std::string gltf_bounds_problem(const nlohmann::json& doc) {
  const auto array = [&](const char* key) { return doc.contains(key) && doc[key].is_array() ? doc[key] : nlohmann::json::array(); };
  const nlohmann::json buffers = array("buffers"), views = array("bufferViews"), accessors = array("accessors");
  for (std::size_t i = 0; i < views.size(); ++i) {
    const nlohmann::json& v = views[i];
    if (!v.is_object()) return "buffer view " + std::to_string(i) + " is not an object";
    const std::int64_t buffer = member(v, "buffer", -1), offset = member(v, "byteOffset", 0), length = member(v, "byteLength", -1);
    if (buffer < 0 || buffer >= static_cast<std::int64_t>(buffers.size()) || offset < 0 || length < 0 || !buffers[buffer].is_object())
      return "buffer view " + std::to_string(i) + " names no buffer, offset or length";
    const std::int64_t size = member(buffers[buffer], "byteLength", -1);
    if (size < 0 || offset + length > size) return "buffer view " + std::to_string(i) + " ends past its buffer";
  }
  for (std::size_t i = 0; i < accessors.size(); ++i) {
    const nlohmann::json& a = accessors[i];
    if (!a.is_object()) return "accessor " + std::to_string(i) + " is not an object";
    if (!a.contains("bufferView")) continue;  // all zeros (or sparse only): nothing to read
    const std::int64_t view = member(a, "bufferView", -1), offset = member(a, "byteOffset", 0), count = member(a, "count", -1);
    const std::int64_t component = member(a, "componentType", -1);
    const std::string type = a.contains("type") && a["type"].is_string() ? a["type"].get<std::string>() : "";
    const std::int64_t bytes = component == 5120 || component == 5121 ? 1 : component == 5122 || component == 5123 ? 2
                               : component == 5125 || component == 5126 ? 4 : 0;
    const std::int64_t components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4
                                    : type == "MAT2" ? 4 : type == "MAT3" ? 9 : type == "MAT4" ? 16 : 0;
    if (view < 0 || view >= static_cast<std::int64_t>(views.size()) || offset < 0 || count < 0 || bytes == 0 || components == 0)
      return "accessor " + std::to_string(i) + " has no valid buffer view, count, component type or type";
    const std::int64_t element = bytes * components;
    const std::int64_t stride = std::max(member(views[view], "byteStride", element), element);
    if (count > 0 && offset + (count - 1) * stride + element > member(views[view], "byteLength", -1))
      return "accessor " + std::to_string(i) + " ends past its buffer view";
  }
  return {};
}

/// Why one primitive of a glTF mesh must not reach assimp (empty when it may): its mode must be one
/// of the specification's seven, and its vertex count (the index accessor's count, else the POSITION
/// accessor's, 0 without one) must make whole primitives of that mode. assimp 5.2 allocates
/// count - 2 faces for a strip or fan and count - 1 for a line strip in unsigned arithmetic, then
/// writes the first face: fewer vertices than one primitive is a 64 GB request or a write past the
/// end. A LINE_LOOP (mode 2) is refused whatever its count: assimp dereferences a null face while it
/// converts one whose first segment it skipped (line primitives would be dropped anyway).
std::string gltf_primitive_problem(const nlohmann::json& doc, const nlohmann::json& primitive) {
  const std::int64_t mode = member(primitive, "mode", 4);
  if (mode < 0 || mode > 6) return "has no valid mode (expected 0 to 6)";
  if (mode == 2)
    return "is a line loop (mode 2), which assimp cannot import safely; line primitives are not kept: remove it";
  const nlohmann::json* accessors = doc.contains("accessors") && doc["accessors"].is_array() ? &doc["accessors"] : nullptr;
  const auto count_of = [&](const nlohmann::json& reference) -> std::int64_t {
    const std::int64_t a = reference.is_number_unsigned() ? static_cast<std::int64_t>(reference.get<std::uint64_t>()) : -1;
    if (accessors == nullptr || a < 0 || a >= static_cast<std::int64_t>(accessors->size()) || !(*accessors)[a].is_object())
      return -1;
    return member((*accessors)[a], "count", -1);
  };
  std::int64_t count = 0;
  const char* counted = "POSITION";
  if (primitive.contains("indices")) {
    count = count_of(primitive["indices"]);
    counted = "index";
    if (count < 0) return "names no valid index accessor";
  } else if (primitive.contains("attributes") && primitive["attributes"].is_object() &&
             primitive["attributes"].contains("POSITION")) {
    count = count_of(primitive["attributes"]["POSITION"]);
    if (count < 0) return "names no valid POSITION accessor";
  }
  static constexpr const char* kModes[] = {"points", "lines", "line loop", "line strip", "triangles", "triangle strip", "triangle fan"};
  static constexpr std::int64_t kMinimum[] = {0, 0, 2, 2, 0, 3, 3};
  static constexpr std::int64_t kMultiple[] = {1, 2, 1, 1, 3, 1, 1};
  const std::string what = std::string("is ") + kModes[mode] + " (mode " + std::to_string(mode) + ") with " +
                           std::to_string(count) + " " + counted + " entries";
  if (count < kMinimum[mode]) return what + " (it needs at least " + std::to_string(kMinimum[mode]) + ")";
  if (count % kMultiple[mode] != 0) return what + " (it needs a multiple of " + std::to_string(kMultiple[mode]) + ")";
  return {};
}

/// Why assimp must not be given this glTF JSON (empty when it may). JSON that does not parse as the
/// glTF specification requires (UTF-8 included) is refused: assimp 5.2 crashes on some of it (a
/// string that is not UTF-8 in an image's mimeType). So is data outside its bounds
/// (gltf_bounds_problem), an image MIME type without '/' (assimp reads past it), and a primitive
/// that assimp cannot convert safely (gltf_primitive_problem).
std::string gltf_json_problem(std::string_view text) {
  // A key twice in one object: the checks below read the last (nlohmann), assimp's reader finds the
  // first, so what is checked would not be what is imported (a mesh listed twice hid a one-entry
  // strip from the checks, found by gltf_reader_fuzzer).
  std::vector<std::set<std::string>> open_objects;
  std::string twice;
  const auto note_keys = [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) {
      open_objects.emplace_back();
    } else if (event == Event::object_end) {
      if (!open_objects.empty()) open_objects.pop_back();
    } else if (event == Event::key && twice.empty() && !open_objects.empty() && parsed.is_string() &&
               !open_objects.back().insert(parsed.get<std::string>()).second) {
      twice = parsed.get<std::string>();
    }
    return true;
  };
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text, note_keys);
  } catch (const nlohmann::json::exception& e) {
    return std::string("the glTF JSON does not parse: ") + e.what();
  }
  if (!twice.empty()) {
    // The key as printable text, shortened: the message stays one line.
    std::string shown;
    for (const char c : twice.substr(0, 40)) shown += (c >= 0x20 && c < 0x7f) ? c : '?';
    return "the glTF JSON has the key \"" + shown + "\" twice in one object (which one holds is ambiguous)";
  }
  if (!doc.is_object()) return "the glTF JSON is not an object";
  if (const std::string bounds = gltf_bounds_problem(doc); !bounds.empty()) return bounds;
  // assimp takes the subtype after the '/' of an image's MIME type without looking for it.
  if (doc.contains("images") && doc["images"].is_array())
    for (std::size_t i = 0; i < doc["images"].size(); ++i) {
      const nlohmann::json& image = doc["images"][i];
      if (image.is_object() && image.contains("mimeType") &&
          (!image["mimeType"].is_string() || image["mimeType"].get<std::string>().find('/') == std::string::npos))
        return "image " + std::to_string(i) + " has a MIME type without '/' (expected image/png or image/jpeg)";
    }
  if (!doc.contains("meshes") || !doc["meshes"].is_array()) return {};
  const nlohmann::json& meshes = doc["meshes"];
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    if (!meshes[m].is_object() || !meshes[m].contains("primitives") || !meshes[m]["primitives"].is_array()) continue;
    const nlohmann::json& primitives = meshes[m]["primitives"];
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      if (!primitives[p].is_object()) continue;
      const std::string problem = gltf_primitive_problem(doc, primitives[p]);
      if (!problem.empty()) return "mesh " + std::to_string(m) + " primitive " + std::to_string(p) + " " + problem;
    }
  }
  return {};
}

/// True when some importer that claims extension `ext` recognises the content of `file` (read through
/// `io`). assimp, given content the extension's importer refuses, tries every importer's detection
/// in turn, which takes seconds on a few kilobytes of garbage; an asset named by its extension is
/// refused at once instead.
bool recognised(const Assimp::Importer& importer, const std::string& ext, const std::string& file, Assimp::IOSystem* io) {
  for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
    Assimp::BaseImporter* candidate = importer.GetImporter(i);
    if (candidate == nullptr) continue;
    std::set<std::string> extensions;
    candidate->GetExtensionList(extensions);
    if (extensions.count(ext) == 0) continue;
    try {
      if (candidate->CanRead(file, io, true)) return true;
    } catch (const std::exception&) {
      // a detector that throws has not recognised the file
    }
  }
  return false;
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
  if (ext == "glb") {
    Result<std::string> bytes = read_file_bounded(path, limits.max_file_bytes, "mesh file");
    if (!bytes) return bytes.error();
    const std::string problem = glb_container_problem(
        std::span(reinterpret_cast<const std::uint8_t*>(bytes->data()), bytes->size()));
    if (!problem.empty()) return Error{path.string() + ": not a binary glTF 2.0 file: " + problem};
    const std::string json_problem =
        gltf_json_problem(glb_json(std::span(reinterpret_cast<const std::uint8_t*>(bytes->data()), bytes->size())));
    if (!json_problem.empty()) return Error{path.string() + ": " + json_problem};
  } else if (ext == "gltf") {
    Result<std::string> text = read_file_bounded(path, limits.max_file_bytes, "mesh file");
    if (!text) return text.error();
    if (const std::string problem = gltf_json_problem(*text); !problem.empty()) return Error{path.string() + ": " + problem};
  }
  Assimp::Importer importer;
  // Every file assimp opens goes through the confinement (the importer owns and deletes it).
  auto* io = new ConfinedIOSystem(path, limits.max_file_bytes);
  importer.SetIOHandler(io);
  if (!recognised(importer, ext, path.string(), io))
    return Error{path.string() + ": not a valid ." + ext + " file (assimp's reader for ." + ext + " does not recognise it)"};
  Result<Mesh> mesh = import_scene(importer, path.string(), limits, [&] { return importer.ReadFile(path.string(), kImportFlags); });
  // A refused reference fails the import, whatever assimp made of the asset without it.
  if (!io->refusal().empty()) return Error{path.string() + ": " + io->refusal()};
  return mesh;
}

Result<Mesh> read_asset_bytes(std::span<const std::uint8_t> bytes, std::string_view extension, const std::string& name,
                              const MeshReadLimits& limits) {
  if (bytes.size() > limits.max_file_bytes)
    return Error{name + ": larger than the limit of " + std::to_string(limits.max_file_bytes) +
                 " bytes per mesh file (the file has " + std::to_string(bytes.size()) + " bytes)"};
  if (bytes.empty()) return Error{name + ": empty file"};
  const std::string hint = normalised_extension(extension);
  if (hint == "glb") {
    if (const std::string problem = glb_container_problem(bytes); !problem.empty())
      return Error{name + ": not a binary glTF 2.0 file: " + problem};
    if (const std::string problem = gltf_json_problem(glb_json(bytes)); !problem.empty()) return Error{name + ": " + problem};
  } else if (hint == "gltf") {
    if (const std::string problem = gltf_json_problem(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        !problem.empty())
      return Error{name + ": " + problem};
  }
  Assimp::Importer importer;
  // assimp reads the memory through its own wrapper of the importer's file access, which would open
  // any other name the asset gives: that access opens none (the importer owns and deletes it).
  auto* files = new ConfinedIOSystem({}, limits.max_file_bytes);
  importer.SetIOHandler(files);
  {
    Assimp::MemoryIOSystem io(bytes.data(), bytes.size(), importer.GetIOHandler());
    if (!recognised(importer, hint, std::string(AI_MEMORYIO_MAGIC_FILENAME) + "." + hint, &io))
      return Error{name + ": not a valid ." + hint + " file (assimp's reader for ." + hint + " does not recognise it)"};
  }
  Result<Mesh> mesh = import_scene(importer, name, limits, [&] {
    return importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags, hint.c_str());
  });
  if (!files->refusal().empty()) return Error{name + ": " + files->refusal()};
  return mesh;
}

}  // namespace shatter
