#pragma once
//! Element correspondences (Section 2.5 of the mesh quilting paper): nearest input face for each
//! output vertex in the overlap (Eq. 1 distance), the three prunings, and element relations.

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

struct CorrespondenceOptions {
  double lambda = 1.0;               //!< weight of distance in Eq. 1 (>= 0; the paper uses 1)
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
  std::vector<int32_t> pairs;  //!< indices into Correspondences::pairs, ascending
};

struct Correspondences {
  std::vector<VertexFacePair> pairs;       //!< survivors of all three prunings, by (out_element, out_vertex)
  std::vector<ElementRelation> relations;  //!< by decreasing pairs.size(), then (out_element, in_element)
};

//! Finds pairs for every vertex of `out_elements` for which in_overlap(vertex) holds, against all
//! faces of all `in_elements` (nearest by Eq. 1, D = (1 + lambda Dist)(1 + |n_v - n_f|), with
//! area-weighted unit vertex normals of the output and unit face normals of the input; exact
//! minimum through an Embree radius-shrinking query), then prunes
//!  (a) opposite normals: n_v . n_f < 0;
//!  (b) distance > max_distance_factor x the local mean edge length of the input face: the mean
//!      length of the distinct input edges with an endpoint at one of the face's three vertices;
//!  (c) relations whose elements' x-y projections do not overlap (exact 2D test between their
//!      closed projected triangles; touching counts as overlap), with all their pairs.
//! Vertices that no triangle uses get no pair. in_overlap is called once per output vertex, from
//! the calling thread; the face queries then run in parallel (TBB) with a deterministic result.
//! out_elements  #E_out meshes; in_elements  #E_in meshes (`elements` ids are ignored in both)
//! \throw InputError (invalid_option) for lambda < 0 or non-finite, max_distance_factor <= 0 or NaN
//!        (infinity turns pruning (b) off);
//!        InputError for a triangle index out of range.
Correspondences find_correspondences(const std::vector<TriMesh>& out_elements,
                                     const std::vector<TriMesh>& in_elements,
                                     const std::function<bool(const Vec3&)>& in_overlap,
                                     const CorrespondenceOptions& options = {});

//! The faces of a swatch's elements, indexed once for every patch's correspondences (a patch's
//! inputs are some of these elements, each moved by the patch's translation).
class SwatchFaces {
 public:
  explicit SwatchFaces(const std::vector<TriMesh>& elements);
  ~SwatchFaces();
  SwatchFaces(const SwatchFaces&) = delete;
  SwatchFaces& operator=(const SwatchFaces&) = delete;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  friend Correspondences find_correspondences(const std::vector<TriMesh>&, const std::vector<TriMesh>&,
                                              const SwatchFaces&, const std::vector<int32_t>&, const glm::dvec2&,
                                              const std::function<bool(const Vec3&)>&, const CorrespondenceOptions&);
};

//! find_correspondences for inputs that are the swatch's elements `sources` (ascending, one per
//! input) moved by `translation`, in_elements[i] being that moved copy of element sources[i]: the
//! same pairs, found in `swatch`'s BVH (with the faces moved as the inputs are) rather than in a
//! BVH built for the call. \throw std::invalid_argument when the sizes differ.
Correspondences find_correspondences(const std::vector<TriMesh>& out_elements,
                                     const std::vector<TriMesh>& in_elements, const SwatchFaces& swatch,
                                     const std::vector<int32_t>& sources, const glm::dvec2& translation,
                                     const std::function<bool(const Vec3&)>& in_overlap,
                                     const CorrespondenceOptions& options = {});

//! Whether the x-y projections of closed triangles (a0, a1, a2) and (b0, b1, b2) share a point.
//! Exact (orientation predicates); a collinear projection counts as the union of its edges.
bool projected_triangles_overlap(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                 const Vec3& b0, const Vec3& b1, const Vec3& b2);

//! Whether the x-y projections of two meshes' triangles overlap (any pair of triangles does).
//! Grid-accelerated over the common bounding box; exact per triangle pair.
bool projections_overlap(const TriMesh& a, const TriMesh& b);

}  // namespace meshquilt
