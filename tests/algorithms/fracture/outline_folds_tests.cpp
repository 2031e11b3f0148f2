// Folds of a cut outline (outline_folds.h): spikes of no area become flat cap triangles, the rest
// of the outline is left for the triangulation. Checked on outlines whose folds are known by
// construction.

#include "algorithms/core/predicates.h"
#include "algorithms/fracture/plane_slice/outline_folds.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <span>
#include <utility>
#include <vector>

using namespace shatter;

namespace {

bool has_edge(const std::vector<CapEdge>& edges, std::int32_t a, std::int32_t b) {
  return std::find(edges.begin(), edges.end(), CapEdge{a, b}) != edges.end();
}

/// Directed edges as a chain: a -> b and b -> a cancel.
using Chain = std::map<std::pair<std::int32_t, std::int32_t>, int>;
void add(Chain& chain, std::int32_t a, std::int32_t b) {
  const int sign = a < b ? 1 : -1;
  const auto key = std::minmax(a, b);
  if ((chain[{key.first, key.second}] += sign) == 0) chain.erase({key.first, key.second});
}

/// The flat triangles' boundary plus what is left is the outline given: nothing lost, nothing added.
void check_closes(std::span<const Vec2> points, const std::vector<CapEdge>& edges, const std::vector<Triangle>& flat,
                  const std::vector<CapEdge>& unfolded) {
  Chain given;
  Chain made;
  for (const CapEdge& e : edges) add(given, e[0], e[1]);
  for (const CapEdge& e : unfolded) add(made, e[0], e[1]);
  for (const Triangle& t : flat) {
    CHECK(orient2d(points[static_cast<std::size_t>(t[0])], points[static_cast<std::size_t>(t[1])],
                   points[static_cast<std::size_t>(t[2])]) == 0);
    for (int k = 0; k < 3; ++k) add(made, t[k], t[(k + 1) % 3]);
  }
  CHECK(made == given);
}

}  // namespace

TEST_CASE("outline folds: a square without a fold is left alone", "[plane-slice][cap]") {
  const std::vector<Vec2> points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<CapEdge> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<CapEdge> unfolded = {{7, 7}};
  CHECK(remove_outline_folds(points, edges, unfolded).empty());
  CHECK(unfolded == std::vector<CapEdge>{{7, 7}});  // untouched
}

TEST_CASE("outline folds: a spike out of a square's side becomes one flat triangle and a shortcut",
          "[plane-slice][cap]") {
  // The right side runs from 1 up to 4, back down to 5 (between 1 and 4: a fold at 4), then up to 2.
  const std::vector<Vec2> points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 0.75}, {1, 0.5}};
  const std::vector<CapEdge> edges = {{0, 1}, {1, 4}, {4, 5}, {5, 2}, {2, 3}, {3, 0}};
  std::vector<CapEdge> unfolded;
  const std::vector<Triangle> flat = remove_outline_folds(points, edges, unfolded);
  REQUIRE(flat.size() == 1);
  check_closes(points, edges, flat, unfolded);
  // The side is straight again (1 -> 5 -> 2 or 1 -> 4 -> 2, by which fold was taken first).
  CHECK(unfolded.size() == 5);
  CHECK_FALSE((has_edge(unfolded, 4, 5) || has_edge(unfolded, 5, 4)));
}

TEST_CASE("outline folds: a spike that doubles back past its start is taken off, and a spike that returns to an "
          "existing edge cancels it", "[plane-slice][cap]") {
  // The spike 1 -> 4 -> 5 comes back past 1 (5 lies below 1 on x = 1): still a fold at 4.
  {
    const std::vector<Vec2> points = {{0, 0}, {1, 0.5}, {1, 2}, {0, 2}, {1, 1}, {1, 0}};
    const std::vector<CapEdge> edges = {{0, 5}, {5, 1}, {1, 4}, {4, 5}, {5, 2}, {2, 3}, {3, 0}};
    std::vector<CapEdge> unfolded;
    const std::vector<Triangle> flat = remove_outline_folds(points, edges, unfolded);
    REQUIRE_FALSE(flat.empty());
    check_closes(points, edges, flat, unfolded);
    // What is left is the quadrilateral 0 -> 5 -> 2 -> 3: the spike and the run 5 -> 1 cancelled.
    CHECK(unfolded.size() == 4);
    CHECK(has_edge(unfolded, 0, 5));
    CHECK(has_edge(unfolded, 5, 2));
  }
  // Collinear but not turned back (a straight run through 4): no fold.
  {
    const std::vector<Vec2> points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 0.5}};
    const std::vector<CapEdge> edges = {{0, 1}, {1, 4}, {4, 2}, {2, 3}, {3, 0}};
    std::vector<CapEdge> unfolded;
    CHECK(remove_outline_folds(points, edges, unfolded).empty());
  }
}
