#pragma once
//! Element correspondences (Section 2.5 of the mesh quilting paper): nearest input face for each
//! output vertex in the overlap (Eq. 1 distance), the three prunings, and element relations.

#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

struct CorrespondenceOptions {
  double lambda = 1.0;               //!< weight of distance in Eq. 1
  double max_distance_factor = 3.0;  //!< prune pairs farther than this x the input's local mean edge length
};

//! One output vertex and its nearest input face by Eq. 1.
struct VertexFacePair {
  int32_t out_element = -1;  //!< index into `out_elements`
  int32_t out_vertex = -1;   //!< vertex index inside that element
  int32_t in_element = -1;   //!< index into `in_elements`
  int32_t in_face = -1;      //!< face index inside that element
  Vec3 closest{0.0};         //!< closest point on the face (the paper's h_in)
  Vec3 barycentric{0.0};     //!< of `closest` (alpha, beta, gamma of Eq. 6)
  double distance = 0.0;     //!< Euclidean distance to `closest`
};

//! An output element related to an input element, with the indices of their pairs.
struct ElementRelation {
  int32_t out_element = -1;
  int32_t in_element = -1;
  std::vector<int32_t> pairs;  //!< indices into Correspondences::pairs
};

struct Correspondences {
  std::vector<VertexFacePair> pairs;       //!< the pairs that survived all three prunings
  std::vector<ElementRelation> relations;  //!< sorted by decreasing pairs.size(), then indices
};

//! Finds pairs for every vertex of `out_elements` for which in_overlap(vertex) holds, against all
//! faces of all `in_elements` (nearest by Eq. 1, with per-vertex normals of the output and face
//! normals of the input), prunes (a) opposite normals (dot < 0), (b) distance larger than
//! max_distance_factor x the mean edge length of the input face's 1-ring, (c) relations whose
//! elements' x-y projections do not overlap (exact 2D triangle overlap), with their pairs.
Correspondences find_correspondences(const std::vector<TriMesh>& out_elements,
                                     const std::vector<TriMesh>& in_elements,
                                     const std::function<bool(const Vec3&)>& in_overlap,
                                     const CorrespondenceOptions& options = {});

}  // namespace meshquilt
