#include "harness/report/fragments_folder.h"

#include "algorithms/core/asset_reference.h"
#include "algorithms/core/bounded_read.h"
#include "harness/limits.h"
#include "harness/results/fragment_writer.h"
#include "harness/results/json_finite.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstring>
#include <system_error>

namespace shatter {
namespace fs = std::filesystem;
namespace {

using Json = nlohmann::json;

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return v;
}

/// A non-negative integer at `key` of `object`, or `fallback` when absent; throws a message otherwise.
std::uint64_t count_at(const Json& object, const char* key, std::uint64_t fallback, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned()) throw std::string(where + "." + key + ": expected a non-negative integer");
  return it->get<std::uint64_t>();
}

/// Bytes per element of an accessor's componentType and type, or 0 when either is not glTF's.
std::uint64_t element_bytes(std::uint64_t component, const std::string& type) {
  const std::uint64_t size = component == 5120 || component == 5121 ? 1
                             : component == 5122 || component == 5123 ? 2
                             : component == 5125 || component == 5126 ? 4
                                                                      : 0;
  const std::uint64_t n = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4
                          : type == "MAT4" ? 16 : 0;
  return size * n;
}

/// Checks the binary glTF `bytes` (glTF 2.0 container, one JSON chunk, at most one BIN chunk; every
/// buffer view inside the BIN chunk, every accessor inside its view) and counts its nodes, triangles
/// and URI images into `out`. Throws the message of the first fault.
void check_glb(const std::string& bytes, ReportFragments& out) {
  if (bytes.size() < 20) throw std::string("shorter than a glTF binary header");
  if (bytes.compare(0, 4, "glTF") != 0) throw std::string("not a glTF binary (no glTF magic)");
  if (u32_at(bytes, 4) != 2) throw fmt::format("glTF binary version {}, expected 2", u32_at(bytes, 4));
  if (u32_at(bytes, 8) != bytes.size())
    throw fmt::format("truncated or padded: the header says {} bytes, the file has {}", u32_at(bytes, 8), bytes.size());
  const std::uint64_t json_length = u32_at(bytes, 12);
  if (u32_at(bytes, 16) != 0x4E4F534Au || 20 + json_length > bytes.size()) throw std::string("the JSON chunk is missing or cut");
  std::uint64_t bin_length = 0;
  const std::uint64_t bin_at = 20 + json_length;
  if (bin_at < bytes.size()) {
    if (bin_at + 8 > bytes.size()) throw std::string("the BIN chunk header is cut");
    bin_length = u32_at(bytes, static_cast<std::size_t>(bin_at));
    if (u32_at(bytes, static_cast<std::size_t>(bin_at + 4)) != 0x004E4942u || bin_at + 8 + bin_length > bytes.size())
      throw std::string("the BIN chunk is missing or cut");
  }
  Json doc;
  try {
    doc = Json::parse(bytes.substr(20, static_cast<std::size_t>(json_length)));
  } catch (const Json::exception&) {
    throw std::string("the JSON chunk is not JSON");
  }
  if (!doc.is_object()) throw std::string("the JSON chunk is not an object");
  const auto list = [&](const char* key) -> const Json& {
    static const Json empty = Json::array();
    const auto it = doc.find(key);
    if (it == doc.end()) return empty;
    if (!it->is_array()) throw fmt::format("{}: expected an array", key);
    return *it;
  };
  const Json& views = list("bufferViews");
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::string where = fmt::format("bufferViews[{}]", i);
    if (!views[i].is_object()) throw where + ": expected an object";
    if (count_at(views[i], "buffer", 0, where) != 0) throw where + ".buffer: only the binary chunk (0) is read";
    const std::uint64_t end = count_at(views[i], "byteOffset", 0, where) + count_at(views[i], "byteLength", 0, where);
    if (end > bin_length) throw fmt::format("{}: ends at byte {} of a binary chunk of {}", where, end, bin_length);
  }
  const Json& accessors = list("accessors");
  for (std::size_t i = 0; i < accessors.size(); ++i) {
    const std::string where = fmt::format("accessors[{}]", i);
    const Json& a = accessors[i];
    if (!a.is_object() || !a.contains("type") || !a["type"].is_string()) throw where + ": expected a typed accessor";
    const std::uint64_t size = element_bytes(count_at(a, "componentType", 0, where), a["type"].get<std::string>());
    if (size == 0) throw where + ": unknown componentType or type";
    const std::uint64_t view = count_at(a, "bufferView", views.size(), where);
    if (view >= views.size()) throw where + ".bufferView: not a buffer view of the file";
    const Json& v = views[static_cast<std::size_t>(view)];
    const std::uint64_t stride = std::max(count_at(v, "byteStride", 0, where), size);
    const std::uint64_t n = count_at(a, "count", 0, where);
    if (n > 0 && count_at(a, "byteOffset", 0, where) + (n - 1) * stride + size > count_at(v, "byteLength", 0, where))
      throw where + ": runs past its buffer view";
  }
  const Json& meshes = list("meshes");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const std::string where = fmt::format("meshes[{}]", m);
    if (!meshes[m].is_object() || !meshes[m].contains("primitives") || !meshes[m]["primitives"].is_array())
      throw where + ": expected primitives";
    for (const Json& p : meshes[m]["primitives"]) {
      if (!p.is_object()) throw where + ": a primitive is not an object";
      const std::uint64_t index = count_at(p, "indices", accessors.size(), where);
      if (index >= accessors.size()) throw where + ": a primitive without indices in the file";
      out.triangles += count_at(accessors[static_cast<std::size_t>(index)], "count", 0, where) / 3;
    }
  }
  out.fragments = list("nodes").size();
  const Json& images = list("images");
  for (std::size_t i = 0; i < images.size(); ++i) {
    const std::string where = fmt::format("images[{}]", i);
    if (!images[i].is_object()) throw where + ": expected an object";
    const auto uri = images[i].find("uri");
    if (uri == images[i].end()) continue;  // embedded in the binary chunk
    if (!uri->is_string()) throw where + ".uri: expected a string";
    out.images.emplace_back(uri->get<std::string>(), std::string());
  }
}

std::string text_at(const Json& j, const char* key, const std::string& file) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_string()) throw fmt::format("{}: {}: expected a string", file, key);
  return it->get<std::string>();
}

std::int64_t integer_at(const Json& j, const char* key, const std::string& file) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number_integer()) throw fmt::format("{}: {}: expected an integer", file, key);
  return it->get<std::int64_t>();
}

}  // namespace

Result<ReportFragments> read_fragments_folder(const fs::path& folder) {
  ReportFragments out;
  out.folder = folder.string();
  const fs::path summary_file = folder / kFragmentsSummaryFile;
  Result<std::string> text = read_file_bounded(summary_file, kMaxResultsFileBytes, "fragments summary");
  if (!text) return text.error();
  Result<nlohmann::ordered_json> parsed = parse_results_json(*text, summary_file.string());
  if (!parsed) return parsed.error();
  const Json j = Json(*parsed);
  const std::string name = summary_file.string();
  try {
    if (!j.is_object() || text_at(j, "kind", name) != "fracture")
      throw name + ": kind: expected \"fracture\" (a summary written by fracture --out or table --out)";
    if (integer_at(j, "schema_version", name) != 1)
      throw fmt::format("{}: schema_version {}: this shatterbench reads fragments folders of version 1", name,
                        j["schema_version"].dump());
    out.algorithm = text_at(j, "algorithm", name);
    if (!j.contains("input") || !j["input"].is_object()) throw name + ": input: expected an object";
    out.mesh = fs::path(text_at(j["input"], "file", name + ": input")).filename().string();
    out.seed = integer_at(j, "seed", name);
    out.requested = integer_at(j, "requested", name);
  } catch (const std::string& message) {
    return Error{message};
  }
  out.summary = std::move(*parsed);
  const fs::path glb_file = folder / "fragments.glb";
  Result<std::string> glb = read_file_bounded(glb_file, kMaxResultsFileBytes, "fragments glTF binary");
  if (!glb) return glb.error();
  out.glb = std::move(*glb);
  try {
    check_glb(out.glb, out);
  } catch (const std::string& message) {
    return Error{glb_file.string() + ": " + message};
  }
  for (auto& [uri, bytes] : out.images) {
    Result<fs::path> file = resolve_reference(folder, uri, kMaxTextureBytes, glb_file.string() + ": image");
    if (!file) return file.error();
    Result<std::string> read = read_file_bounded(*file, kMaxTextureBytes, "image");
    if (!read) return read.error();
    bytes = std::move(*read);
  }
  return out;
}

Result<std::vector<ReportFragments>> find_fragments_folders(const fs::path& folder) {
  std::vector<fs::path> found;
  std::error_code ec;
  if (fs::is_regular_file(folder / kFragmentsSummaryFile, ec)) {
    found.push_back(folder);
  } else {
    fs::recursive_directory_iterator it(folder, fs::directory_options::none, ec), end;
    if (ec) return Error{folder.string() + ": cannot read the folder: " + ec.message()};
    for (; it != end; it.increment(ec)) {
      if (ec) return Error{folder.string() + ": cannot read the folder: " + ec.message()};
      if (it.depth() >= kMaxFragmentsFolderDepth) it.disable_recursion_pending();
      if (!it->is_directory(ec) || it->is_symlink(ec)) {
        if (it->is_symlink(ec)) it.disable_recursion_pending();
        continue;
      }
      if (fs::is_regular_file(it->path() / kFragmentsSummaryFile, ec)) {
        found.push_back(it->path());
        it.disable_recursion_pending();
      }
    }
  }
  if (found.empty())
    return Error{folder.string() + ": a directory with no fragments folder (" + kFragmentsSummaryFile +
                 " and fragments.glb, from fracture --out or table --out) in it or below it"};
  std::sort(found.begin(), found.end());
  std::vector<ReportFragments> out;
  for (const fs::path& f : found) {
    Result<ReportFragments> one = read_fragments_folder(f);
    if (!one) return one.error();
    out.push_back(std::move(*one));
  }
  return out;
}

}  // namespace shatter
