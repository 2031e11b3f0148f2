// The folders of the source tree form layers (docs/design.md, "Layers"): a file may include files of
// its own room and of rooms in lower layers only. This test reads every `#include "..."` of the tree
// and fails on an include that points sideways or upwards, naming the file, the line and both rooms.

#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#ifndef SHATTER_SOURCE_DIR
#error "tests need SHATTER_SOURCE_DIR (a compile definition of the test target)"
#endif

namespace {

namespace fs = std::filesystem;

/// The layers, lowest first. A room is a folder with everything below it; rooms of one layer are
/// independent of each other. The longest matching room prefix decides a file's room.
const std::vector<std::vector<std::string>>& layers() {
  static const std::vector<std::vector<std::string>> l = {
      {"algorithms/core"},
      {"algorithms/fracture", "algorithms/bonds", "algorithms/repair", "algorithms/assets"},
      {"algorithms/stress"},
      {"algorithms/registry"},
      {"harness/signals"},
      {"harness/limits.h", "harness/output", "harness/process", "harness/plugins"},
      {"harness/cases", "harness/metrics"},
      {"harness/results"},
      {"harness/pipeline", "harness/stability"},
      {"harness/grid", "harness/accuracy", "harness/compare"},
      {"harness/history"},
      {"harness/report"},
      {"harness/cli"},
      {"fixtures"},
      {"benchmarks", "fuzz", "tests/support"},
      {"tests"},
  };
  return l;
}

struct Room {
  std::string name;
  int layer = 0;
};

/// The room of a path relative to the source root, or none when no room holds it.
std::optional<Room> room_of(const std::string& path) {
  std::optional<Room> best;
  for (int layer = 0; layer < static_cast<int>(layers().size()); ++layer)
    for (const std::string& room : layers()[layer]) {
      const bool inside = path == room || (path.size() > room.size() && path.compare(0, room.size(), room) == 0 &&
                                           path[room.size()] == '/');
      if (inside && (!best || room.size() > best->name.size())) best = Room{room, layer};
    }
  return best;
}

/// A file's room for the rule: a test folder (tests/X) is its own room in the "tests" layer, so tests of
/// one folder do not include another's.
Room rule_room(const std::string& path, Room room) {
  if (room.name == "tests") {
    const std::size_t slash = path.find('/', 6);
    if (slash != std::string::npos) room.name = path.substr(0, slash);
  }
  return room;
}

struct Violation {
  std::string where;
  std::string what;
};

std::vector<Violation> layer_violations(const fs::path& root, int& files_read, int& includes_read) {
  static const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<Violation> out;
  for (const char* top : {"algorithms", "harness", "fixtures", "benchmarks", "fuzz", "tests"}) {
    if (!fs::exists(root / top)) continue;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      const std::string path = fs::relative(e.path(), root).generic_string();
      const std::optional<Room> own = room_of(path);
      if (!own) {
        out.push_back({path, "is in no room of the layer list"});
        continue;
      }
      const Room from = rule_room(path, *own);
      ++files_read;
      std::ifstream in(e.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        std::smatch m;
        if (!std::regex_search(line, m, include_line)) continue;
        const std::string target = m[1].str();
        // Quoted includes of the same folder by bare name ("voronoi_cells.h") stay inside the room.
        if (target.find('/') == std::string::npos) continue;
        ++includes_read;
        const std::optional<Room> to_room = room_of(target);
        const std::string where = path + ":" + std::to_string(number);
        if (!to_room) {
          out.push_back({where, "includes " + target + ", which is in no room of the layer list"});
          continue;
        }
        const Room to = rule_room(target, *to_room);
        if (to.name == from.name) continue;
        if (to.layer >= from.layer)
          out.push_back({where, from.name + " (layer " + std::to_string(from.layer) + ") includes " + target + " of " +
                                    to.name + " (layer " + std::to_string(to.layer) + ")"});
      }
    }
  }
  return out;
}

}  // namespace

TEST_CASE("layers: no folder includes a folder above or beside it", "[layers]") {
  int files = 0;
  int includes = 0;
  const std::vector<Violation> violations = layer_violations(SHATTER_SOURCE_DIR, files, includes);
  // The tree is there: an empty scan would pass for the wrong reason.
  REQUIRE(files > 200);
  REQUIRE(includes > 500);
  std::string listed;
  for (const Violation& v : violations) listed += "\n  " + v.where + ": " + v.what;
  INFO("includes against the layers (docs/design.md, \"Layers\"):" << listed);
  CHECK(violations.empty());
}

TEST_CASE("layers: the rule catches an upward and a sideways include", "[layers]") {
  const fs::path root = fs::temp_directory_path() / ("shatter_layers_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "algorithms/core");
  fs::create_directories(root / "algorithms/bonds");
  fs::create_directories(root / "algorithms/fracture");
  std::ofstream(root / "algorithms/core/mesh.h") << "#pragma once\n#include \"algorithms/fracture/fracturer.h\"\n";
  std::ofstream(root / "algorithms/bonds/graph.h") << "#include \"algorithms/fracture/fracturer.h\"\n";
  std::ofstream(root / "algorithms/fracture/fracturer.h") << "#include \"algorithms/core/mesh.h\"\n";
  int files = 0;
  int includes = 0;
  const std::vector<Violation> v = layer_violations(root, files, includes);
  fs::remove_all(root);
  CHECK(files == 3);
  CHECK(includes == 3);
  REQUIRE(v.size() == 2);
  std::vector<std::string> where{v[0].where, v[1].where};
  std::sort(where.begin(), where.end());
  CHECK(where[0] == "algorithms/bonds/graph.h:1");
  CHECK(where[1] == "algorithms/core/mesh.h:2");
}
