/// libFuzzer target: a fracturer's result of arbitrary content, checked by check_fracture_output (the
/// check every plugin's result passes, algorithms/fracture/fracture_output_check.h) against a unit
/// cube. The bytes are read as fragment meshes in the binary form of mesh_codec.h (unchecked: the
/// codec's own checks are skipped), each with mass properties either its mesh's or taken from the
/// bytes. The check must never crash, and a result it accepts must be one that later stages can use:
/// indices in range, one tag per triangle, closed fragments, volumes summing to the cube's.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/fracture_output_check.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

/// Reads values of type T from the front of the input; zero once it runs out.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  template <class T>
  T take() {
    T value{};
    if (at_ + sizeof(T) <= size_) std::memcpy(&value, data_ + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  [[nodiscard]] bool left() const { return at_ < size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const shatter::Mesh cube = shatter::make_box(shatter::Vec3(1, 1, 1));
  Bytes in(data, size);
  std::vector<shatter::Fragment> fragments;
  const int count = in.take<std::uint8_t>() % 9;
  for (int f = 0; f < count && in.left(); ++f) {
    shatter::Fragment fragment;
    // Either a half of the cube (a valid start the fuzzer can mutate) or a mesh from the bytes.
    if (in.take<std::uint8_t>() % 2 == 0) {
      fragment.mesh = shatter::make_box(shatter::Vec3(0.5, 1, 1), shatter::Vec3(f % 2 == 0 ? -0.25 : 0.25, 0, 0));
    }
    const int vertices = in.take<std::uint8_t>() % 16;
    for (int v = 0; v < vertices; ++v) {
      const double x = in.take<double>(), y = in.take<double>(), z = in.take<double>();
      fragment.mesh.vertices.emplace_back(x, y, z);
    }
    const int triangles = in.take<std::uint8_t>() % 24;
    for (int t = 0; t < triangles; ++t) {
      fragment.mesh.triangles.push_back({in.take<std::int32_t>() % 40, in.take<std::int32_t>() % 40, in.take<std::int32_t>() % 40});
      fragment.mesh.tags.push_back(static_cast<shatter::FaceTag>(in.take<std::uint8_t>() % 4));
    }
    if (in.take<std::uint8_t>() % 3 == 0 && !fragment.mesh.tags.empty()) fragment.mesh.tags.pop_back();
    fragment.mass = shatter::is_closed_and_oriented(fragment.mesh) ? shatter::mass_properties(fragment.mesh)
                                                                   : shatter::MassProperties{};
    if (in.take<std::uint8_t>() % 4 == 0) fragment.mass.volume = in.take<double>();
    fragments.push_back(std::move(fragment));
  }
  const shatter::Status s = shatter::check_fracture_output(cube, fragments, "fuzz");
  if (!s) {
    if (s.error().message.empty() || s.error().message.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  // Accepted: safe and right to use.
  double sum = 0.0;
  for (const shatter::Fragment& f : fragments) {
    if (f.mesh.tags.size() != f.mesh.triangles.size()) std::abort();
    for (const shatter::Triangle& t : f.mesh.triangles)
      for (const std::int32_t i : t)
        if (i < 0 || static_cast<std::size_t>(i) >= f.mesh.vertices.size()) std::abort();
    if (!shatter::is_closed_and_oriented(f.mesh)) std::abort();
    sum += shatter::mass_properties(f.mesh).volume;
  }
  if (!(std::abs(sum - 1.0) <= 1e-6)) std::abort();
  return 0;
}
