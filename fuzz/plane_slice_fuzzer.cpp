/// libFuzzer target: slice a small valid solid (a cube or a tetrahedron) by a fuzzer-chosen plane, and
/// fracture it with a fuzzer-chosen seed and fragment count. Every output fragment must be closed and
/// oriented with finite coordinates, and the fragment volumes must sum to the input's; aborts otherwise.
///
/// Input layout (missing bytes read as zero): byte 0 picks the solid and the mode, then 6 doubles
/// (plane point, plane normal; non-finite values are legal input and must be refused cleanly), then a
/// 64-bit seed and one byte for the fragment count (1 to 16).

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

using namespace shatter;

/// Reads fixed-size values from the fuzzer's bytes, zero past the end.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  template <class T>
  T take() {
    unsigned char buffer[sizeof(T)] = {};
    const std::size_t n = pos_ < size_ ? std::min(sizeof(T), size_ - pos_) : 0;
    if (n > 0) std::memcpy(buffer, data_ + pos_, n);
    pos_ += sizeof(T);
    T value;
    std::memcpy(&value, buffer, sizeof(T));
    return value;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

Mesh make_tetrahedron() {
  Mesh m;
  m.add_vertex({0.0, 0.0, 0.0});
  m.add_vertex({1.0, 0.0, 0.0});
  m.add_vertex({0.0, 1.0, 0.0});
  m.add_vertex({0.0, 0.0, 1.0});
  m.add_triangle(0, 2, 1, FaceTag::surface);
  m.add_triangle(0, 1, 3, FaceTag::surface);
  m.add_triangle(0, 3, 2, FaceTag::surface);
  m.add_triangle(1, 2, 3, FaceTag::surface);
  return m;
}

[[noreturn]] void violation(const char* what) {
  std::fprintf(stderr, "plane_slice_fuzzer: %s\n", what);
  std::abort();
}

void check_fragments(const std::vector<Fragment>& fragments, double input_volume) {
  double total = 0.0;
  for (const Fragment& f : fragments) {
    if (!all_finite(f.mesh)) violation("fragment with a non-finite coordinate");
    if (!is_closed_and_oriented(f.mesh)) violation("fragment not closed and oriented");
    if (f.mesh.tags.size() != f.mesh.triangles.size()) violation("tag count differs from triangle count");
    total += signed_volume(f.mesh);
  }
  if (fragments.empty()) violation("no fragment");
  // Exact predicates keep every piece closed; the volumes are sums of rounded products, so a
  // relative 1e-9 is a generous bound for a unit-sized solid cut by planes through it or near it.
  if (!(std::abs(total - input_volume) <= 1e-9 * input_volume)) violation("volume not conserved");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const auto mode = in.take<std::uint8_t>();
  const Mesh solid = (mode & 1) != 0 ? make_tetrahedron() : make_box(Vec3(1.0, 1.0, 1.0));
  const double volume = signed_volume(solid);
  Plane plane;
  for (int i = 0; i < 3; ++i) plane.point[i] = in.take<double>();
  for (int i = 0; i < 3; ++i) plane.normal[i] = in.take<double>();
  const auto seed = in.take<std::uint64_t>();
  const int count = 1 + in.take<std::uint8_t>() % 16;

  const PlaneSliceFracturer slicer;
  if ((mode & 2) == 0) {
    const Plane planes[] = {plane};
    Result<std::vector<Fragment>> fragments = slicer.fracture_by_planes(solid, planes);
    if (fragments) check_fragments(*fragments, volume);
  } else {
    FractureParams params;
    params.fragments = count;
    params.seed = seed;
    Result<std::vector<Fragment>> fragments = slicer.fracture(solid, params);
    if (!fragments) violation("valid parameters refused");
    check_fragments(*fragments, volume);
  }
  return 0;
}
