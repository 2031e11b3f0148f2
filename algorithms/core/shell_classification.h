#pragma once
/// Classification of a closed mesh's shells: which ones bound material, which ones are cavities, and
/// which arrangements describe no solid at all.
///
/// Design note: a closed, consistently oriented mesh can still describe no solid. Its connected
/// shells each have an orientation (the sign of their volume) and may lie inside one another; the
/// mesh is a solid exactly when its winding number is 0 or 1 everywhere, that is when no two shells
/// cross, every outermost shell faces outward and orientations alternate going inward (outward
/// shell, cavity, island in the cavity, ...). Anything else (two nested outward shells, an inward
/// shell inside nothing, shells that cross) counts some volume twice or negatively, and every
/// fracturer then returns nonsense. A mesh whose outermost shells all face inward is the same
/// solid turned inside out: it reads as a solid once every triangle is reversed.
///
/// Cost: one pass over the triangles for a single shell (almost every mesh), and for shells whose
/// bounding boxes are pairwise apart (a sweep over the boxes). Otherwise an exact test of the
/// triangle pairs of different shells (self_intersection.h, O(#F) on a surface-like mesh), then one
/// winding-number query per shell against each shell whose bounding box holds a point of it, the
/// candidates found through a uniform grid of those points.

#include "algorithms/core/mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shatter {

/// One connected shell of a closed mesh.
struct Shell {
  std::vector<std::int32_t> triangles;  ///< indices into mesh.triangles, ascending
  double volume = 0.0;                  ///< signed volume, m^3: positive for an outward shell
  int container = -1;                   ///< the innermost shell holding this one, -1 when none
  /// True when the shell faces outward (positive volume).
  [[nodiscard]] bool outward() const { return volume > 0.0; }
};

/// What a mesh's shells describe.
enum class SolidVerdict {
  solid,          ///< outward shells, none inside another, none crossing another
  with_cavities,  ///< a solid with cavities: an inward shell inside an outward one (and so on inward)
  invalid,        ///< no solid: crossing shells, nested shells of one orientation, an inward shell inside nothing
};

/// The shells of a mesh and the verdict on them.
struct ShellClassification {
  std::vector<Shell> shells;  ///< in the order of their first triangle
  /// Every outermost shell faces inward: the verdict is the one for the mesh with every triangle
  /// reversed (a whole solid read inside out).
  bool inverted = false;
  SolidVerdict verdict = SolidVerdict::solid;
  /// For with_cavities and invalid: one line naming the shells (see shell_name), else empty.
  std::string reason;
};

/// Splits the closed, consistently oriented `mesh` (is_closed_and_oriented) into its shells
/// (triangles connected through shared vertices) and classifies them (see the design note). A point
/// of each shell is tested against the other shells by winding number (winding_number.h), which is
/// exact enough because shells that do not cross keep a positive distance apart.
ShellClassification classify_shells(const Mesh& mesh);

/// "shell <index> (<n> triangles from triangle <first>)": how messages name a shell.
std::string shell_name(const ShellClassification& shells, int index);

}  // namespace shatter
