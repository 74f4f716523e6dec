#pragma once
//! Stitching two cut elements into one (Section 2.7 of the mesh quilting paper, after Yu et al.
//! 2004's mesh merging): cut-boundary loops, loop pairing, dynamic-programming alignment of each
//! loop pair, Eq. 5 deformation toward the averaged seam, and welding along the seam.

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "quilt/merging/cut_loops.h"

namespace meshquilt {

struct StitchOptions {
  double mu = 100.0;             //!< Eq. 5 weight of the seam and anchor constraints (the paper's
                                 //!< mu, raised from 1 so both are met nearly exactly and the bend
                                 //!< is confined between them)
  double anchor_factor = 4.0;    //!< only vertices within this many mean edge lengths of a seam
                                 //!< point move: Eq. 5 is solved on the band of faces touching
                                 //!< them, its outer vertices held in place; 0: whole parts
  double min_split = 0.15;       //!< a seam point may split a boundary edge only between this
                                 //!< fraction and 1 - it of the edge (a nearer projection is moved
                                 //!< to that bound; welding to the end is the DP's other choice)
  int32_t start_candidates = 4;  //!< starting correspondences tried per loop pair (nearest first)
  bool check_intersections = true;  //!< reject seams whose faces meet faces they share no vertex
                                    //!< with (exact triangles_intersect over a local grid)
};

struct StitchResult {
  bool ok = false;
  std::string failure;      //!< why stitching was refused (empty when ok)
  TriMesh mesh;             //!< the stitched element (when ok)
  int32_t loop_pairs = 0;   //!< seam loops welded
};

//! Stitches the kept faces of `a` and of `b` into one mesh. Cut loops of the two parts are paired
//! one-to-one by mean distance; each pair is aligned by dynamic programming over the two closed
//! polylines (every seam point is a vertex pair welded together or a vertex splitting the other
//! loop's edge; the total distance between matched points is minimized over a few starting
//! correspondences); both parts are deformed by Eq. 5 (uniform Laplacian) with their loop
//! vertices pulled to the averaged seam, within anchor_factor of it; the seam is then welded
//! exactly, splitting a boundary face into a fan where points fall inside its edge (never
//! nearer than min_split of the edge to an end). No new triangles span a gap, so the seam has no
//! T-junctions and no slivers. The result must be one connected component, every seam face
//! non-degenerate and oriented like the face it came from, and, when both inputs are closed
//! oriented 2-manifolds, a closed oriented 2-manifold without pinched vertices; otherwise the
//! result is refused (ok = false). Parts lie to the left of their loops (consistent outward
//! orientation of both inputs).
//! Steps (stitching.cpp): cut_out_side, pair_loops, align_loop_pair, deform_seam_band, weld_seam,
//! split_fans, check_seam.
//! \pre keep_a is #F of a, keep_b is #F of b; vertices welded (shared by index).
//! \throw SolverError when the deformation solve fails.
StitchResult stitch_parts(const TriMesh& a, const std::vector<uint8_t>& keep_a, const TriMesh& b,
                          const std::vector<uint8_t>& keep_b, const StitchOptions& options = {});

}  // namespace meshquilt
