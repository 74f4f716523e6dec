#pragma once
//! Nearest-face lists over a voxel grid of a triangle mesh: for every voxel, the faces that can
//! come closest to a point in it, and a distance `reach` that every other face keeps from every
//! point of the voxel. A query then needs one voxel and a short list, and knows from `reach`
//! whether the list decided its answer. Geometry matching uses it twice: its kernel bounds
//! Eq. 2 with one voxel fetch per pair, and the host evaluates Eq. 2 exactly from the same lists.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Entries [first, end) of a voxel's list whose faces share a label, and the first entry's `near`,
//! which bounds them all: one read decides whether the group can matter.
struct FaceGroup {
  uint32_t first;
  uint32_t end;
  uint32_t label;
  float near;
};

struct NearFaceGrid {
  Vec3 origin{0.0};          //!< lower corner of voxel (0, 0, 0)
  double voxel = 0.0;        //!< voxel edge
  glm::ivec3 size{0};        //!< voxels along x, y, z (x fastest)
  Vec3 box_low{0.0};         //!< the faces' bounding box
  Vec3 box_high{0.0};
  std::vector<uint32_t> start;  //!< #voxels + 1 offsets into `faces`
  std::vector<uint32_t> faces;  //!< listed faces per voxel, in increasing `near`
  //! Per listed face: no point of the voxel is nearer to it than this (rounded
  //! down to float, which halves the lists' memory), so a scan of the list may stop at the first
  //! entry that cannot beat what it has.
  std::vector<float> near;
  //! Per voxel: every face not in its list is at least this far from every point of the voxel
  //! (0 when nothing is known). Both bounds also hold a little past the voxel's walls (1e-6 of
  //! a voxel), for points rounded into a neighbour.
  std::vector<double> reach;
  //! Per voxel that lists no face, the face nearest its centre (-1 elsewhere): a start for a
  //! search from a point in it, whose answer lies on the swatch's side facing it.
  std::vector<int32_t> nearest_face;
  //! Each voxel's list in groups of faces with one label (`face_groups` of build_near_face_grid;
  //! one group without labels), each group in increasing `near`: voxel v's groups are
  //! groups[group_start[v], group_start[v + 1]). A scan then stops per group, and skips groups it
  //! can rule out.
  std::vector<uint32_t> group_start;  //!< #voxels + 1
  std::vector<FaceGroup> groups;

  //! The voxel holding q (x fastest), or -1 outside the grid.
  int64_t voxel_of(const Vec3& q) const;
};

//! Builds the lists for `mesh` with voxels of edge `voxel` (coarsened so that there are at most
//! `max_voxels`) over its bounding box grown by `margin`. A voxel lists the faces within
//! `list_margin` plus the voxel's diagonal of the face nearest its centre (the nearest
//! `max_list` of them); voxels whose centre is farther than `far` from every face list none, and
//! their reach is the nearest face's distance from the centre less half the voxel's diagonal.
//! `face_groups` (#F labels, or empty for one group) groups each list by label, ascending.
//! Parallel; exact in double.
//! \pre mesh has faces; voxel, margin, list_margin and far are positive and finite.
NearFaceGrid build_near_face_grid(const TriMesh& mesh, double voxel, double margin, double list_margin, double far,
                                  int max_list = 48, int64_t max_voxels = int64_t{1} << 18,
                                  const std::vector<uint32_t>& face_groups = {});

}  // namespace meshquilt
