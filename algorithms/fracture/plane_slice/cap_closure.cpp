#include "algorithms/fracture/plane_slice/cap_closure.h"

namespace shatter {
namespace {

std::uint64_t directed_key(std::int32_t a, std::int32_t b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

bool cap_closes_outline(std::span<const Triangle> cap, std::span<const CapEdge> outline, HalfEdgeCounts& counts) {
  counts.clear();
  for (const Triangle& t : cap)
    for (int k = 0; k < 3; ++k) ++counts[directed_key(t[k], t[(k + 1) % 3])];
  for (const CapEdge& e : outline) {
    const auto it = counts.find(directed_key(e[0], e[1]));
    if (it == counts.end() || it->second == 0) return false;
    --it->second;
  }
  for (const auto& [key, count] : counts) {
    if (count == 0) continue;
    const auto a = static_cast<std::int32_t>(key >> 32);
    const auto b = static_cast<std::int32_t>(key & 0xffffffffu);
    const auto twin = counts.find(directed_key(b, a));
    if (twin == counts.end() || twin->second != count) return false;
  }
  return true;
}

}  // namespace shatter
