#pragma once
//! Yarn lengths of a woven texture: each closed element taken as a tube of constant cross-section,
//! whose area A = 2 pi r L and volume V = pi r^2 L give its length L = A^2 / (4 pi V) and radius
//! r = 2 V / A whatever its path (ends add about one radius each).

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Length and radius of each element taken as a tube; 0 for an element that encloses no volume
//! (open, or flat). `face_element` is #F element ids in [0, elements), faces outward.
struct TubeMeasures {
  std::vector<double> length;  //!< #elements
  std::vector<double> radius;  //!< #elements
};
TubeMeasures tube_measures(const TriMesh& mesh, const std::vector<int32_t>& face_element, int32_t elements);

//! The median radius of the elements that are tubes (length > 0), and how many there are.
double median_tube_radius(const TubeMeasures& tubes, int32_t* count = nullptr);

//! The length-weighted median of `lengths` (zeros left out): the length L such that yarns no
//! longer than L make up half the total length. 0 when there is none.
double length_weighted_median(std::vector<double> lengths);

}  // namespace meshquilt
