#pragma once
//! The distinct elements of a repeating swatch's pattern: swatch elements that are copies of one
//! another at a period form one class, so the pattern holds one element of each class at each
//! period. A class whose element no other element of the pattern would be merged with can be
//! placed straight at its periods: the patch step would leave it as it is.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "quilt/quilt_swatch.h"
#include "quilt/swatch_lattice.h"

namespace meshquilt {

struct LatticeClass {
  int32_t element = -1;      //!< the swatch element standing for the class
  glm::dvec2 centroid{0.0};  //!< x-y mean of its vertices, swatch frame
  //! No element of another class, nor of this one at another period, would be its merge partner
  //! (mean pair distance within `partner_distance`); nor does another class lie at the same place.
  bool alone = false;
};

//! The classes of `swatch`'s elements under the periods of `lattice`, in the order of their first
//! element; elements are copies when their vertices match within `tolerance` (same_element).
std::vector<LatticeClass> lattice_classes(const QuiltSwatch& swatch, const SwatchLattice& lattice,
                                          double partner_distance, double tolerance);

}  // namespace meshquilt
