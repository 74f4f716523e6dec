#pragma once
//! Pairs of intersecting faces of a mesh: between different elements (elements passing through
//! each other) and within one element (self-intersections), by an Embree broad phase and the
//! exact triangle-triangle test.

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Which face pairs to report.
enum class IntersectionScope {
  different_elements,  //!< faces of different elements (touching counts as intersecting)
  same_element,        //!< faces of one element that share no vertex index ("adjacent" faces,
                       //!< sharing a vertex or an edge, are never reported)
};

using FacePair = std::pair<int32_t, int32_t>;

//! Both scopes from one broad phase.
struct FaceIntersections {
  std::vector<FacePair> different_elements;  //!< sorted, first < second
  std::vector<FacePair> same_element;        //!< sorted, first < second
};

//! Intersecting face pairs of `mesh` in both scopes.
//! face_element  #F element id per face (e.g. face_components after welding; weld first so that
//!               adjacency by vertex index means adjacency in space)
//! \throw InputError when face_element does not have one entry per face; DeviceError/SolverError
//!        from the BVH.
FaceIntersections find_intersecting_faces(const TriMesh& mesh, const std::vector<int32_t>& face_element);

//! find_intersecting_faces after the faces of the elements marked in `moved` (by element id) were
//! moved: `before` was found with the faces where they were. Only pairs with a face of a moved
//! element are tested again, among the elements whose bounds meet a moved one's. The same result
//! as testing every face again.
FaceIntersections find_intersecting_faces_again(const TriMesh& mesh, const std::vector<int32_t>& face_element,
                                                const FaceIntersections& before, const std::vector<uint8_t>& moved);

//! Intersecting face pairs (f, g), f < g, in lexicographic order, for one scope. Exact
//! (Guigue-Devillers with exact predicates) over Embree's BVH-against-BVH candidate pairs,
//! in parallel. Same preconditions and errors as find_intersecting_faces.
std::vector<FacePair> intersecting_face_pairs(const TriMesh& mesh, const std::vector<int32_t>& face_element,
                                              IntersectionScope scope);

}  // namespace meshquilt
