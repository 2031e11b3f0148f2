#include "algorithms/fracture/plane_slice/outline_folds.h"

#include "algorithms/core/predicates.h"

#include <cstddef>
#include <cstdint>

namespace shatter {
namespace {

/// a -> b -> c runs out along a line and back: exactly collinear, the second step turned against the first.
bool is_fold(std::span<const Vec2> points, std::int32_t a, std::int32_t b, std::int32_t c) {
  if (a == c) return false;
  const Vec2& pa = points[static_cast<std::size_t>(a)];
  const Vec2& pb = points[static_cast<std::size_t>(b)];
  const Vec2& pc = points[static_cast<std::size_t>(c)];
  return orient2d(pa, pb, pc) == 0 && (pb - pa).dot(pc - pb) < 0.0;
}

/// The outline as a graph whose edges can be removed and added while folds are taken off.
class OutlineGraph {
 public:
  OutlineGraph(std::size_t point_count, std::span<const CapEdge> edges)
      : edges_(edges.begin(), edges.end()), alive_(edges.size(), true), in_(point_count), out_(point_count) {
    for (std::size_t i = 0; i < edges_.size(); ++i) link(i);
  }

  /// The one live edge into and the one out of `b`, when it has exactly one of each.
  bool single_path(std::int32_t b, std::size_t& in_edge, std::size_t& out_edge) const {
    return only_live(in_[static_cast<std::size_t>(b)], in_edge) && only_live(out_[static_cast<std::size_t>(b)], out_edge);
  }

  [[nodiscard]] const CapEdge& edge(std::size_t i) const { return edges_[i]; }
  void remove(std::size_t i) { alive_[i] = false; }

  /// Adds a -> c, or removes c -> a when it is there (the two would bound nothing).
  void add_or_cancel(std::int32_t a, std::int32_t c) {
    for (const std::size_t i : out_[static_cast<std::size_t>(c)])
      if (alive_[i] && edges_[i][1] == a) {
        alive_[i] = false;
        return;
      }
    edges_.push_back({a, c});
    alive_.push_back(true);
    link(edges_.size() - 1);
  }

  [[nodiscard]] std::vector<CapEdge> live_edges() const {
    std::vector<CapEdge> live;
    for (std::size_t i = 0; i < edges_.size(); ++i)
      if (alive_[i]) live.push_back(edges_[i]);
    return live;
  }

 private:
  void link(std::size_t i) {
    out_[static_cast<std::size_t>(edges_[i][0])].push_back(i);
    in_[static_cast<std::size_t>(edges_[i][1])].push_back(i);
  }
  bool only_live(const std::vector<std::size_t>& list, std::size_t& found) const {
    int live = 0;
    for (const std::size_t i : list)
      if (alive_[i]) {
        found = i;
        ++live;
      }
    return live == 1;
  }

  std::vector<CapEdge> edges_;
  std::vector<bool> alive_;
  std::vector<std::vector<std::size_t>> in_;
  std::vector<std::vector<std::size_t>> out_;
};

/// Whether any point has one edge in, one out and a fold between them (one pass, no allocation per edge).
bool has_fold(std::span<const Vec2> points, std::span<const CapEdge> edges) {
  std::vector<std::int32_t> in_count(points.size(), 0);
  std::vector<std::int32_t> out_count(points.size(), 0);
  std::vector<std::int32_t> from(points.size(), -1);
  std::vector<std::int32_t> to(points.size(), -1);
  for (const CapEdge& e : edges) {
    ++out_count[static_cast<std::size_t>(e[0])];
    to[static_cast<std::size_t>(e[0])] = e[1];
    ++in_count[static_cast<std::size_t>(e[1])];
    from[static_cast<std::size_t>(e[1])] = e[0];
  }
  for (std::size_t b = 0; b < points.size(); ++b)
    if (in_count[b] == 1 && out_count[b] == 1 && is_fold(points, from[b], static_cast<std::int32_t>(b), to[b]))
      return true;
  return false;
}

}  // namespace

std::vector<Triangle> remove_outline_folds(std::span<const Vec2> points, std::span<const CapEdge> edges,
                                           std::vector<CapEdge>& unfolded) {
  std::vector<Triangle> flat;
  if (!has_fold(points, edges)) return flat;
  OutlineGraph graph(points.size(), edges);
  std::vector<std::int32_t> pending(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) pending[p] = static_cast<std::int32_t>(p);
  while (!pending.empty()) {
    const std::int32_t b = pending.back();
    pending.pop_back();
    std::size_t in_edge = 0;
    std::size_t out_edge = 0;
    if (!graph.single_path(b, in_edge, out_edge)) continue;
    const std::int32_t a = graph.edge(in_edge)[0];
    const std::int32_t c = graph.edge(out_edge)[1];
    if (!is_fold(points, a, b, c)) continue;
    flat.push_back({a, b, c});
    graph.remove(in_edge);
    graph.remove(out_edge);
    graph.add_or_cancel(a, c);
    // The shortcut may have made a fold at either end.
    pending.push_back(a);
    pending.push_back(c);
  }
  unfolded = graph.live_edges();
  return flat;
}

}  // namespace shatter
