#pragma once
//! Element merging (Section 2.7 of the mesh quilting paper): graph cuts on the dual graphs of a
//! related output/input element pair (Eq. 7 weights, the paper's source/sink rules, Boykov-
//! Kolmogorov max-flow) and stitching of the two cut parts into one connected component.

#include <functional>
#include <string>

#include "mesh/tri_mesh.h"
#include "quilt/merging/stitching.h"

namespace meshquilt {

//! Distances below are multiples of the larger mean edge length of the two elements.
struct MergeOptions {
  double coverage_factor = 1.5;  //!< a face or vertex is "covered" by the other element when it
                                 //!< lies within this distance of it (the paper's "has a
                                 //!< corresponding vertex", robust to different tessellations)
  double frontier_factor = 2.0;  //!< x coverage distance: faces this close to an uncovered face of
                                 //!< the other element count as "adjacent to a face with no
                                 //!< corresponding vertices" (paper's SINK rule)
  double depth_factor = 4.0;     //!< x coverage distance: covered output faces farther than this
                                 //!< inside the overlap (along the surface) are deleted: the
                                 //!< input replaces the output there
  double seam_margin_factor = 1.5;  //!< input faces this close to the output's cut loops carry no
                                    //!< terminal link, so the input's cut may follow them freely
  StitchOptions stitch;             //!< seam alignment, Eq. 5 deformation, checks
};

enum class MergeOutcome {
  kept_out,  //!< the input lay within the overlap, added nothing, or a failed stitch found the
             //!< output more complete: output kept whole
  kept_in,   //!< the output lay within the overlap, or a failed stitch found the input more
             //!< complete: the input element replaces it whole
  stitched,  //!< cut and stitched into one connected component
};

struct MergeResult {
  MergeOutcome outcome = MergeOutcome::kept_out;
  TriMesh element;        //!< the element to keep (no `elements` ids)
  std::string fallback;   //!< why a stitch was abandoned for a whole element (empty otherwise)
  int32_t seam_loops = 0; //!< loop pairs welded when stitched
};

//! Merges a related pair. `in_overlap(p)` tells whether a point lies in the overlapping region
//! (a face is inside when its centroid is). Faces outside the overlap are kept (SOURCE); the
//! result is one connected component, a closed 2-manifold whenever both inputs were; when a
//! clean stitch is impossible, the more complete element is kept whole instead.
//! Steps: (1) an element wholly inside the overlap yields to the other (output first); (2) the
//! output element is cut by a minimum cut on its dual graph, Eq. 7 weights with Dist to the input.
//! SOURCE: faces outside the overlap, then faces near where the input ends inside the overlap.
//! SINK (the paper's rule): faces around vertices close to the input whose closest input face
//! lies outside the overlap or near input faces the output does not cover; also covered faces
//! deep inside the overlap, where the input replaces the output. (3) The input element is cut to
//! complement it: input faces nearest kept output faces SINK, nearest deleted ones (or alone,
//! outside the overlap) SOURCE, a margin around the output's cut loops free, Eq. 7 weights with
//! the distance to those loops; the margin narrows (x1, x0.5, x0) until a stitch succeeds.
//! (4) stitch_parts welds the two parts.
//! "More complete" = more faces outside the overlap (ties: more faces, then the output). The
//! fallback element is returned unchanged (not deformed). Typical cost: a few milliseconds for
//! elements of a thousand faces (two Embree BVHs, two max-flows, two small Eq. 5 solves).
//! \pre both elements are welded triangle meshes, consistently oriented (outward).
//! A seam deformation that fails to solve (SolverError) also leads to the fallback.
//! \throw InputError for non-finite positions (NaN capacities or targets); indices are not
//!        range-checked.
MergeResult merge_elements(const TriMesh& out_element, const TriMesh& in_element,
                           const std::function<bool(const Vec3&)>& in_overlap,
                           const MergeOptions& options = {});

}  // namespace meshquilt
