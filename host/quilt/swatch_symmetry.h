#pragma once
//! The rotational symmetry of a swatch about its z axis: the turns a surface layout may use to
//! continue it across a seam without the texture changing (surface/seamless_layout.h).

#include <glm/mat3x3.hpp>

#include "quilt/patch_step.h"

namespace meshquilt {

//! What tells one element kind from another: its source and its vertices' second moments about
//! their centroid.
struct ElementShape {
  int32_t source = -1;
  glm::dvec2 centre{0.0};  //!< x-y of the centroid
  glm::dmat3 moments{0.0};

  //! Whether this element turned through `angle` about z has `other`'s shape, within 5%.
  bool matches_turned(const ElementShape& other, double angle) const;
};

//! The shape of every element of the swatch, in element order.
std::vector<ElementShape> element_shapes(const QuiltSwatch& swatch);

//! 2 when turning the swatch through a half turn about z maps every element kind to one of the
//! same source (for each element, some element of its source has the turned element's shape,
//! second moments about the centroid, within 5%), else 1. Translations do not count, so this is a
//! symmetry of the pattern's kinds, not of the finite swatch. Quarter turns are never taken on
//! their own: one carries a warp onto a weft, which look alike but are not the same yarns (a
//! weave's wefts follow the field), and sources do not always tell them apart; ask for 4 with
//! `--symmetry 4` where a quarter turn is a symmetry.
int rotational_symmetry(const QuiltSwatch& swatch);

//! Whether turning the swatch through `angle` about z maps every element kind to one of the same
//! source, as rotational_symmetry tests it.
bool symmetric_under(const QuiltSwatch& swatch, double angle);

}  // namespace meshquilt
