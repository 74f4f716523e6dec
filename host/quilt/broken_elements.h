#pragma once
//! The clean-up pass (Section 4 of the mesh quilting paper): elements that could not be made
//! whole are removed, and counted.

#include <vector>

#include "mesh/tri_mesh.h"
#include "spatial/intersecting_pairs.h"

namespace meshquilt {

struct BrokenElements {
  int open = 0;          //!< not closed 2-manifolds although the swatch's elements are
  int folded = 0;        //!< passed through themselves although the swatch's elements do not
  int intersecting = 0;  //!< removed because they passed through others
  int intersecting_face_pairs = 0;  //!< face pairs of different elements that met, before removal
};

//! Marks broken elements dead in `alive` (#elements): when `swatch_closed`, every element that
//! is not a closed 2-manifold; when `swatch_unfolded`, every element two of whose faces that share
//! no vertex meet (deformation or embedding folded it); then, while alive elements intersect (exact tests), the one that
//! intersects the most alive others (ties: fewer faces, then the later one), so that as few
//! elements go as possible. `known`, when given, are the intersecting faces of the alive elements
//! joined in order (as a placement that tested them last found them): used where no element is
//! open, instead of testing again.
BrokenElements remove_broken_elements(const std::vector<const TriMesh*>& elements, bool swatch_closed,
                                      bool swatch_unfolded, std::vector<uint8_t>& alive,
                                      const FaceIntersections* known = nullptr);

}  // namespace meshquilt
