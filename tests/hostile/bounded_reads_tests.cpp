// Hostile inputs, every read bounded: whatever a file is (a device, a pipe, a sparse giant, a link to
// /dev/zero) and whatever its line endings, a reader holds no more than the documented limit before
// it refuses, and a number in a mesh file is read whole or refused with the file and the line.

#include "tests/hostile/hostile_support.h"
#include "algorithms/core/bounded_read.h"
#include "algorithms/core/mesh_io.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using shatter::test::line_count;
using shatter::test::run_cli_argv;

namespace fs = std::filesystem;
using shatter::test::hostile_scratch;
using shatter::test::put_file;

namespace {

/// A sparse file of `bytes` bytes: no disk blocks, but its size says it all.
fs::path sparse(const fs::path& path, std::uintmax_t bytes) {
  put_file(path, "{");
  fs::resize_file(path, bytes);
  return path;
}

/// One refusal from the CLI: exit 2 and one line holding every word of `words`.
void require_refused(const std::vector<std::string>& args, const std::vector<std::string>& words) {
  const auto r = run_cli_argv(args);
  std::string command;
  for (const std::string& a : args) command += a + " ";
  INFO(command << "\n" << r.err);
  CHECK(r.exit_code == 2);
  CHECK(line_count(r.err) == 1);
  CHECK(r.err.rfind("shatterbench: error: ", 0) == 0);
  for (const std::string& w : words) CHECK(r.err.find(w) != std::string::npos);
}

std::string error_of(const Result<Mesh>& mesh) { return mesh.ok() ? std::string("(no error)") : mesh.error().message; }

}  // namespace

TEST_CASE("reads: one bounded read refuses devices, folders and files past the limit", "[hostile][reads]") {
  const fs::path dir = hostile_scratch("bounded");
  const fs::path exact = put_file(dir / "exact.txt", std::string(100, 'x'));
  const Result<std::string> at_limit = read_file_bounded(exact, 100, "test file");
  REQUIRE(at_limit.ok());
  CHECK(at_limit->size() == 100);
  const Result<std::string> over = read_file_bounded(exact, 99, "test file");
  REQUIRE_FALSE(over.ok());
  CHECK(over.error().message == exact.string() + ": larger than the limit of 99 bytes per test file (the file has 100 bytes)");
  CHECK(read_file_bounded(put_file(dir / "empty.txt", ""), 0, "test file").ok());

  fs::create_symlink("/dev/zero", dir / "zero");
  fs::create_symlink("/dev/urandom", dir / "random");
  fs::create_symlink(dir / "missing", dir / "dangling");
  const std::vector<std::pair<fs::path, std::string>> refused = {
      {"/dev/zero", "character device"},      {dir / "zero", "character device"}, {dir / "random", "character device"},
      {"/dev/null", "character device"},      {dir, "a directory"},               {dir / "dangling", "cannot open"},
      {dir / "missing.txt", "cannot open"}};
  for (const auto& [path, why] : refused) {
    const Result<std::string> r = read_file_bounded(path, 1 << 20, "test file");
    INFO(path.string());
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.error().message, StartsWith(path.string() + ": ") && Contains(why));
  }

  // A pipe has no size: it is refused as soon as what was read passes the limit, with the writer
  // still writing (8 MB into a limit of 64 KiB).
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const auto previous = std::signal(SIGPIPE, SIG_IGN);  // the writer sees EPIPE when the reader stops
  std::thread writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    const std::string block(1 << 16, 'y');
    for (int i = 0; fd >= 0 && i < 128; ++i)
      if (::write(fd, block.data(), block.size()) < 0) break;
    if (fd >= 0) ::close(fd);
  });
  const Result<std::string> piped = read_file_bounded(fifo, 1 << 16, "test file");
  writer.join();
  std::signal(SIGPIPE, previous);
  REQUIRE_FALSE(piped.ok());
  CHECK(piped.error().message == fifo.string() + ": larger than the limit of 65536 bytes per test file");

  // A pipe within the limit reads whole.
  std::thread small_writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    if (fd >= 0) {
      CHECK(::write(fd, "OFF\n", 4) == 4);
      ::close(fd);
    }
  });
  const Result<std::string> small = read_file_bounded(fifo, 1 << 16, "test file");
  small_writer.join();
  REQUIRE(small.ok());
  CHECK(*small == "OFF\n");
}

TEST_CASE("reads: results files of compare, merge and report are bounded", "[hostile][reads][cli]") {
  const fs::path dir = hostile_scratch("results");
  fs::create_symlink("/dev/zero", dir / "zero.json");
  const std::string zero = (dir / "zero.json").string();
  const std::string giant = sparse(dir / "giant.json", (1ULL << 30) + 1).string();
  const std::string folder = (dir / "folder.json").string();
  fs::create_directories(folder);
  const std::string out = (dir / "out").string();
  for (const std::string& bad : {zero, giant, folder}) {
    const std::string why = bad == giant ? "larger than the limit of 1073741824 bytes per results file"
                                         : (bad == zero ? "character device" : "a directory");
    const std::string other = (dir / "other.json").string();  // read after `bad`: never reached
    require_refused({"compare", bad, other}, {bad, why});
    require_refused({"merge", bad, other, "--out", out + ".json"}, {bad, why});
    require_refused({"report", bad, "--out", out}, {bad, why});
    CHECK_FALSE(fs::exists(out + ".json"));
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("reads: case files are bounded wherever they are read", "[hostile][reads][cli]") {
  const fs::path dir = hostile_scratch("cases");
  const fs::path case_dir = dir / "cases";
  fs::create_directories(case_dir);
  const std::string huge = sparse(case_dir / "huge.json", 100ULL << 20).string();
  const std::string over = sparse(case_dir / "over.json", (16ULL << 20) + 1).string();
  fs::create_symlink("/dev/zero", case_dir / "zero.json");
  put_file(case_dir / "long.json", "{\"description\": \"" + std::string(1 << 20, 'd') + "\\nsecond line\", \"mesh\": {}}");
  put_file(case_dir / "fine.json", R"({"description": "a short one", "mesh": {"box": {"size": [1, 1, 1]}}})");

  for (const std::string& bad : {huge, over}) {
    require_refused({"grid", "--case", bad, "--json", (dir / "out.json").string()},
                    {bad, "larger than the limit of 16777216 bytes per case file"});
    require_refused({"accuracy", "--case", bad}, {bad, "16777216"});
  }
  require_refused({"grid", "--case", (case_dir / "zero.json").string()}, {"zero.json"});

  // `list` reads every case of SHATTER_CASE_DIR: each is one short line whatever its size or content.
  const std::string env = "SHATTER_CASE_DIR=" + case_dir.string();
  ::setenv("SHATTER_CASE_DIR", case_dir.c_str(), 1);
  const auto r = run_cli_argv({"list"});
  ::unsetenv("SHATTER_CASE_DIR");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.size() < 20000);
  CHECK(r.out.find("a short one") != std::string::npos);
  CHECK(r.out.find("second line") == std::string::npos);  // cut and escaped, never a second line
  std::size_t start = 0;
  for (std::size_t end; (end = r.out.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = r.out.substr(start, end - start);
    CHECK(line.size() < 300);
    if (line.find("  huge ") == 0 || line.find("  over ") == 0) CHECK_THAT(line, Contains("larger than the limit"));
  }
  CHECK(r.out.find("  huge ") != std::string::npos);
}

TEST_CASE("reads: mesh limits hold whatever the line endings", "[hostile][reads][mesh_io]") {
  const fs::path dir = hostile_scratch("endings");
  const MeshReadLimits limits{.max_triangles = 20, .max_vertices = 10};
  for (const std::string eol : {"\n", "\r", "\r\n"}) {
    const std::string name = eol == "\n" ? "lf" : (eol == "\r" ? "cr" : "crlf");
    INFO(name);
    // 50 vertices: refused at the 11th, on its own line, whatever ends the lines.
    std::string many;
    for (int i = 0; i < 50; ++i) many += "v " + std::to_string(i) + " 0 0" + eol;
    const fs::path vertices = put_file(dir / (name + "_vertices.obj"), many);
    CHECK_THAT(error_of(read_obj(vertices, limits)),
               StartsWith(vertices.string() + ":11: ") && Contains("limit of 10 vertices"));
    // 3 vertices and 30 faces: refused at the 21st face (line 24).
    std::string faces = "v 0 0 0" + eol + "v 1 0 0" + eol + "v 0 1 0" + eol;
    for (int i = 0; i < 30; ++i) faces += "f 1 2 3" + eol;
    const fs::path triangles = put_file(dir / (name + "_faces.obj"), faces);
    CHECK_THAT(error_of(read_obj(triangles, limits)),
               StartsWith(triangles.string() + ":24: ") && Contains("limit of 20 triangles"));
    // An OFF tetrahedron reads the same; an error names the right line.
    const std::string tet = "OFF" + eol + "4 4 0" + eol + "0 0 0" + eol + "1 0 0" + eol + "0 1 0" + eol + "0 0 1" + eol +
                            "3 0 2 1" + eol + "3 0 1 3" + eol + "3 0 3 2" + eol + "3 1 2 3" + eol;
    const Result<Mesh> off = read_off(put_file(dir / (name + ".off"), tet));
    REQUIRE(off.ok());
    CHECK(off->vertices.size() == 4);
    CHECK(off->triangle_count() == 4);
    const fs::path bad = put_file(dir / (name + "_bad.off"), tet + "3 1 2 3" + eol);
    CHECK_THAT(error_of(read_off(bad)), StartsWith(bad.string() + ":11: ") && Contains("count mismatch"));
    const fs::path header = put_file(dir / (name + "_header.off"), "OFF" + eol + "20 4 0" + eol + "0 0 0" + eol);
    CHECK_THAT(error_of(read_off(header, limits)), StartsWith(header.string() + ":2: ") && Contains("limit of 10"));
  }
  // Mixed endings count every line once ("\r\n" is one end, "\n\r" two).
  const fs::path mixed = put_file(dir / "mixed.obj", "v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\rf 1 2 3\r\nf 1 2 9\n");
  CHECK_THAT(error_of(read_obj(mixed)), StartsWith(mixed.string() + ":6: ") && Contains("out of range"));
  // The file-size limit holds for every format and ending.
  CHECK_THAT(error_of(read_mesh(put_file(dir / "size.obj", std::string(200, '\r')), {.max_file_bytes = 100})),
             Contains("larger than the limit of 100 bytes per mesh file"));
}

TEST_CASE("reads: OBJ numbers and corners are strict", "[hostile][reads][mesh_io]") {
  const fs::path dir = hostile_scratch("obj_numbers");
  const std::string tri = "f 1 2 3\n";
  struct Bad {
    std::string name, text, line, what;
  };
  const std::vector<Bad> bad = {
      {"word", "v 1 1 foo\nv 1 0 0\nv 0 1 0\n" + tri, "1", "non-numeric token 'foo'"},
      {"comma", "v 0 0 0\nv 1,5 2 3\nv 0 1 0\n" + tri, "2", "non-numeric token '1,5'"},
      {"too_few", "v 0 0 0\nv 1 1\nv 0 1 0\n" + tri, "2", "vertex has 2 numbers"},
      {"five", "v 0 0 0 1 1\nv 1 0 0\nv 0 1 0\n" + tri, "1", "vertex has 5 numbers"},
      {"seven", "v 0 0 0 1 1 1 1\nv 1 0 0\nv 0 1 0\n" + tri, "1", "vertex has 7 numbers"},
      {"nan", "v 0 0 0\nv 1 0 0\nv nan 1 0\n" + tri, "3", "non-finite number 'nan'"},
      {"inf", "v 0 0 -inf\nv 1 0 0\nv 0 1 0\n" + tri, "1", "non-finite number '-inf'"},
      {"overflow", "v 0 0 0\nv 1e400 0 0\nv 0 1 0\n" + tri, "2", "outside the range of a double"},
      {"hex", "v 0x10 0 0\nv 1 0 0\nv 0 1 0\n" + tri, "1", "non-numeric token '0x10'"},
      {"weight", "v 0 0 0 2\nv 1 0 0\nv 0 1 0\n" + tri, "1", "vertex weight w = 2"},
      {"colour", "v 0 0 0 1 x 0\nv 1 0 0\nv 0 1 0\n" + tri, "1", "non-numeric token 'x'"},
      {"two_plus", "v ++1 0 0\nv 1 0 0\nv 0 1 0\n" + tri, "1", "non-numeric token '++1'"},
      {"face_word", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "4", "non-numeric token 'x'"},
      {"face_float", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3.0\n", "4", "non-numeric token '3.0'"},
      {"face_two", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "4", "2 corners"},
      {"face_zero", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "4", "vertex index 0"},
      {"face_back", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "4", "before the first vertex"},
      {"face_range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "4", "vertex 4 out of range"},
      {"face_slashes", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "4", "malformed"},
      {"face_texture", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/a 2 3\n", "4", "malformed"},
      {"face_huge", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", "4", "outside the range of 64 bits"},
      {"unknown", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvv 1 2 3\n" + tri, "4", "unknown statement 'vv'"},
      {"free_form", "v 0 0 0\nv 1 0 0\nv 0 1 0\ncurv 0 1 1 2\n" + tri, "4", "free-form geometry"},
  };
  for (const Bad& b : bad) {
    const fs::path path = put_file(dir / (b.name + ".obj"), b.text);
    const std::string message = error_of(read_obj(path));
    INFO(b.name << ": " << message);
    CHECK_THAT(message, StartsWith(path.string() + ":" + b.line + ": ") && Contains(b.what));
  }
  // What the format allows reads as written.
  const std::string good =
      "o part\nv +1 -2 .5\nv 1 2 3 1\nv 0 0 1 0.5 0.5 0.5\nv 1e-400 0 0\nvt 0 0\nvn 0 0 1\ns off\nusemtl stone\n"
      "g cut\nf 1/1 2//1 3/1/1\nl 1 2\np 3\nf -4 -3 -2\n";
  const Result<Mesh> mesh = read_obj(put_file(dir / "good.obj", good));
  REQUIRE(mesh.ok());
  REQUIRE(mesh->vertices.size() == 4);
  CHECK(mesh->vertices[0] == Vec3(1, -2, 0.5));
  CHECK(mesh->vertices[2] == Vec3(0, 0, 1));
  CHECK(mesh->vertices[3] == Vec3(0, 0, 0));
  CHECK(mesh->triangles == std::vector<Triangle>{{0, 1, 2}, {0, 1, 2}});
  CHECK(mesh->tags == std::vector<FaceTag>{FaceTag::cut, FaceTag::cut});
}

TEST_CASE("reads: OFF numbers are strict", "[hostile][reads][mesh_io]") {
  const fs::path dir = hostile_scratch("off_numbers");
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  struct Bad {
    std::string name, text, line, what;
  };
  const std::vector<Bad> bad = {
      {"word", "OFF\n4 4 0\n0 0 0\n1 1 foo\n0 1 0\n0 0 1\n" + faces, "4", "non-numeric token 'foo'"},
      {"comma", "OFF\n4 4 0\n0 0 0\n1,5 2 3\n0 1 0\n0 0 1\n" + faces, "4", "non-numeric token '1,5'"},
      {"too_few", "OFF\n4 4 0\n0 0 0\n1 1\n0 1 0\n0 0 1\n" + faces, "4", "vertex 1 has 2 numbers, expected 3"},
      {"too_many", "OFF\n4 4 0\n0 0 0\n1 1 1 1\n0 1 0\n0 0 1\n" + faces, "4", "vertex 1 has 4 numbers, expected 3"},
      {"nan", "OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n" + faces, "5", "non-finite number 'nan'"},
      {"inf", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 inf\n" + faces, "6", "non-finite number 'inf'"},
      {"overflow", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 -1e309\n" + faces, "6", "outside the range of a double"},
      {"colour_count", "COFF\n4 4 0\n0 0 0 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n0 0 1 1 1 1\n" + faces, "3",
       "expected 6 or 7"},
      {"normal_word", "NOFF\n4 4 0\n0 0 0 0 0 x\n1 0 0 0 0 1\n0 1 0 0 0 1\n0 0 1 0 0 1\n" + faces, "3",
       "non-numeric token 'x'"},
      {"face_colour", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 red\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", "7",
       "non-numeric token 'red'"},
      {"face_extra", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 1 1 1 1 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", "7",
       "a colour has at most 4"},
      {"count_word", "OFF\n4 four 0\n", "2", "non-numeric token 'four'"},
      {"count_extra", "OFF\n4 4 0 0\n", "2", "found more numbers"},
      {"corner_word", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nthree 0 2 1\n", "7", "non-numeric token 'three'"},
  };
  for (const Bad& b : bad) {
    const fs::path path = put_file(dir / (b.name + ".off"), b.text);
    const std::string message = error_of(read_off(path));
    INFO(b.name << ": " << message);
    CHECK_THAT(message, StartsWith(path.string() + ":" + b.line + ": ") && Contains(b.what));
  }
  // Header variants with their extra numbers read, keeping x y z only.
  const Result<Mesh> rgba = read_off(put_file(dir / "rgba.off", "COFF\n4 4 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1 1\n"
                                                             "0 0 1 0 0 0\n" + faces));
  REQUIRE(rgba.ok());
  CHECK(rgba->vertices[1] == Vec3(1, 0, 0));
  const Result<Mesh> stcnoff = read_off(put_file(dir / "stcnoff.off", "STCNOFF\n4 4 0\n0 0 0 0 0 1 1 1 1 0 0\n"
                                                                   "1 0 0 0 0 1 1 1 1 0 1\n0 1 0 0 0 1 1 1 1 1 0\n"
                                                                   "0 0 1 0 0 1 1 1 1 1 1\n" + faces));
  REQUIRE(stcnoff.ok());
  CHECK(stcnoff->vertices[3] == Vec3(0, 0, 1));
}
