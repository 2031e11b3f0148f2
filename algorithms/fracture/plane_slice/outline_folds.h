#pragma once
/// Folds of a cut outline: where the outline runs out along a line and straight back (a spike of no
/// area), which happens when a cut crosses a sliver piece only a few ulps thick. A constrained
/// triangulation cannot cover a region of no area, so such a spike would leave the cap open; instead
/// each fold a -> b -> c (b with one edge in and one out, a, b and c exactly collinear, c turned back
/// towards a) becomes one flat cap triangle (a, b, c) and the outline takes the shortcut a -> c (or
/// loses it, when c -> a is already there). Every outline edge is then matched by a cap half-edge.

#include "algorithms/core/cap_triangulator.h"
#include "algorithms/core/mesh.h"

#include <span>
#include <vector>

namespace shatter {

/// Takes the folds off the directed `edges` over `points` (cap_triangulator.h's convention: the region
/// to cover is on their left): returns the flat triangles that close them, in the same sense as the
/// cap's triangles, and writes the outline without them to `unfolded`. Returns nothing and leaves
/// `unfolded` as it was when there is no fold (the usual case: one linear pass).
std::vector<Triangle> remove_outline_folds(std::span<const Vec2> points, std::span<const CapEdge> edges,
                                           std::vector<CapEdge>& unfolded);

}  // namespace shatter
