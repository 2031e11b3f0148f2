#include "harness/report/html/report_data.h"

#include "harness/report/html/base64.h"
#include "harness/report/html/gzip.h"

#include <nlohmann/json.hpp>

#include <new>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

/// `{"file": ..., "results": ...}` for every item of `files` (each with `file` and `document`).
template <typename Files>
Json entries(const Files& files) {
  Json out = Json::array();
  for (const auto& f : files) out.push_back(Json{{"file", f.file}, {"results", f.document}});
  return out;
}

/// `bytes` gzip-compressed, in base64: how the page carries a binary (it inflates them itself). zlib
/// fails only without memory, which the command reports as such.
std::string packed(std::string_view bytes) {
  Result<std::string> z = gzip(bytes);
  if (!z) throw std::bad_alloc();
  return base64(*z);
}

/// The grid files, each with its recorded frames (the sidecar's bytes, packed) when it has them.
Json grid_entries(const std::vector<ReportGrid>& grids) {
  Json out = entries(grids);
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (!grids[i].recorded_frames.empty()) out[i]["recorded_frames"] = packed(grids[i].recorded_frames);
  return out;
}

/// The media type of an image by its first bytes (the two kinds glTF allows), for a data: URL.
std::string image_type(const std::string& bytes) {
  if (bytes.size() >= 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return "image/png";
  if (bytes.size() >= 3 && bytes.compare(0, 3, "\xff\xd8\xff") == 0) return "image/jpeg";
  return "application/octet-stream";  // the page's loader reports it as an image it cannot decode
}

/// The fragments folders: summary, glTF binary (packed) and the images it names by URI (data: URLs).
Json fragments_entries(const std::vector<ReportFragments>& folders) {
  Json out = Json::array();
  for (const ReportFragments& f : folders) {
    Json images = Json::object();
    for (const auto& [uri, bytes] : f.images) images[uri] = "data:" + image_type(bytes) + ";base64," + base64(bytes);
    out.push_back(Json{{"folder", f.folder},
                       {"algorithm", f.algorithm},
                       {"mesh", f.mesh},
                       {"seed", f.seed},
                       {"requested", f.requested},
                       {"fragments", f.fragments},
                       {"triangles", f.triangles},
                       {"summary", f.summary},
                       {"glb", packed(f.glb)},
                       {"images", std::move(images)}});
  }
  return out;
}

}  // namespace

std::string report_data_json(const ReportInputs& inputs) {
  const Json data = {
      {"format", 1},
      {"grids", grid_entries(inputs.grids)},
      {"accuracy", entries(inputs.accuracies)},
      {"stability", entries(inputs.stabilities)},
      {"tables", entries(inputs.tables)},
      {"fragments", fragments_entries(inputs.fragments)},
  };
  // Strict UTF-8: every string was checked when the file was parsed.
  return data.dump();
}

}  // namespace shatter
