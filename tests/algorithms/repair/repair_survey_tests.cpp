#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/repair/repair_solid.h"
#include "algorithms/repair/solid_check.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace shatter;

// Not a test of its own (hidden tag): the table of docs/repair.md, printed as Markdown.
// Run: build/bin/shatter_tests "[repair-survey]"
TEST_CASE("repair: survey of the data set meshes that the acceptance rule refuses", "[.][repair-survey]") {
  if (!test::have_meshes()) return;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(test::mesh_dir()))
    if (entry.path().extension() == ".off") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::cout << "| mesh | triangles | refused because | repaired | ms | Hausdorff / diagonal | output |\n"
               "|---|---:|---|---|---:|---:|---|\n";
  int refused = 0, passed = 0;
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    Result<Mesh> mesh = read_mesh(path);
    if (!mesh) {
      std::cout << "| " << name << " | | unreadable: " << mesh.error().message << " | | | | |\n";
      continue;
    }
    Mesh copy = *mesh;
    const Result<ValidationReport> valid = validate_solid(copy, name);
    if (valid) continue;
    ++refused;
    std::string reason = valid.error().message.substr(name.size() + 2);
    if (reason.size() > 48) reason = reason.substr(0, 45) + "...";
    const Result<RepairedSolid> result = repair_solid(*mesh, name);
    std::cout << "| " << name << " | " << mesh->triangles.size() << " | " << reason << " | ";
    if (!result) {
      std::cout << "refused: " << result.error().message.substr(name.size() + 2) << " | | | |\n";
      continue;
    }
    const RepairReport& r = result->report;
    std::ostringstream what;
    if (r.vertices_merged > 0) what << r.vertices_merged << " merged, ";
    if (r.faces_removed > 0) what << r.faces_removed << " removed, ";
    if (r.faces_reoriented > 0) what << r.faces_reoriented << " reoriented, ";
    if (r.holes_filled > 0) what << r.holes_filled << " holes (" << std::setprecision(3) << r.hole_area << " m2), ";
    if (r.self_intersections > 0) what << r.self_intersections << " intersecting pairs, ";
    if (!r.self_intersection_fix.empty()) what << r.self_intersection_fix << ", ";
    if (r.sheets_removed > 0) what << r.sheets_removed << " sheets dropped, ";
    what << r.shells << " shells";
    if (r.cavities > 0) what << " (" << r.cavities << " cavities)";
    const double diagonal = bounding_box(*mesh).diagonal();
    const auto defect = repair::solid_defect(result->mesh);
    if (!defect) ++passed;
    std::cout << what.str() << " | " << std::fixed << std::setprecision(0) << r.time_ms << " | "
              << std::scientific << std::setprecision(2) << r.hausdorff_distance / diagonal << std::defaultfloat
              << " | " << (defect ? "FAILS: " + *defect : std::string("solid")) << " |\n";
  }
  std::cout << "\n" << refused << " refused by validate_solid, " << passed << " repaired into solids\n";
}

// The measured choice between plain and refined-and-faired hole filling (docs/repair.md).
// Run: build/bin/shatter_tests "[repair-fill-choice]"
TEST_CASE("repair: plain against refined and faired hole filling", "[.][repair-fill-choice]") {
  struct Shape {
    std::string name;
    Mesh closed;
    double volume;  // analytic
  };
  const double pi = 3.14159265358979323846;
  const std::vector<Shape> shapes = {{"unit cube", make_box(Vec3::Ones()), 1.0},
                                     {"sphere r=1 (64x32)", make_sphere(1.0, 64, 32), 4.0 / 3.0 * pi}};
  std::cout << "| shape, hole | filling | volume error | Hausdorff to the closed shape | ms |\n|---|---|---:|---:|---:|\n";
  for (const Shape& shape : shapes) {
    const double top = bounding_box(shape.closed).max.z();
    for (const double cap : {0.05, 0.3}) {
      Mesh open;
      open.vertices = shape.closed.vertices;
      for (std::size_t f = 0; f < shape.closed.triangles.size(); ++f) {
        const Triangle& t = shape.closed.triangles[f];
        bool drop = true;
        for (int k = 0; k < 3; ++k) drop = drop && shape.closed.vertices[t[k]].z() >= top - cap * 2.0 - 1e-12;
        if (!drop) open.add_triangle(t[0], t[1], t[2], FaceTag::surface);
      }
      for (const bool fair : {false, true}) {
        RepairOptions options;
        options.refine_and_fair_holes = fair;
        const Result<RepairedSolid> result = repair_solid(open, shape.name, options);
        if (!result) {
          std::cout << "| " << shape.name << ", top " << cap * 100 << " % | " << (fair ? "refine+fair" : "plain")
                    << " | " << result.error().message << " | | |\n";
          continue;
        }
        const double error = std::abs(signed_volume(result->mesh) - shape.volume) / shape.volume;
        std::cout << "| " << shape.name << ", top " << cap * 100 << " % of the height | " << (fair ? "refine+fair" : "plain")
                  << " | " << error << " | " << repair::hausdorff_distance(result->mesh, shape.closed) << " | "
                  << result->report.time_ms << " |\n";
      }
    }
  }
}
