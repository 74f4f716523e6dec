#pragma once
//! Element merging (Section 2.7 of the mesh quilting paper): graph cuts on the dual graphs of a
//! related output/input element pair (Eq. 7 weights, the paper's source/sink rules, Boykov-
//! Kolmogorov max-flow) and stitching of the two cut parts into one connected component.

#include <functional>

#include "mesh/tri_mesh.h"

namespace meshquilt {

struct MergeOptions {
  // Implementation-defined tuning (document defaults here).
};

enum class MergeOutcome {
  kept_out,  //!< the input element lay within the overlap (or stitching failed): output kept
  kept_in,   //!< the output element lay within the overlap: input element replaces it
  stitched,  //!< cut and stitched into one connected component
};

struct MergeResult {
  MergeOutcome outcome = MergeOutcome::kept_out;
  TriMesh element;  //!< the element to keep (no `elements` ids)
};

//! Merges a related pair. `in_overlap(p)` tells whether a point lies in the overlapping region
//! (a face is inside when its centroid is). Faces outside the overlap are kept (SOURCE); the
//! result is one connected component, a closed 2-manifold whenever both inputs were; when a
//! clean stitch is impossible, the more complete element is kept whole instead.
MergeResult merge_elements(const TriMesh& out_element, const TriMesh& in_element,
                           const std::function<bool(const Vec3&)>& in_overlap,
                           const MergeOptions& options = {});

}  // namespace meshquilt
