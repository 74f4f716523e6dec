#pragma once
//! Laplacian element deformation (Section 2.6 of the mesh quilting paper, Eq. 4-6).

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A point constraint on a vertex (Eq. 5): w_vertex should be at `target`.
struct VertexConstraint {
  int32_t vertex = -1;
  Vec3 target{0.0};
};

//! A point constraint on a point inside a face (Eq. 6): alpha w1 + beta w2 + gamma w3 at `target`.
struct FaceConstraint {
  int32_t face = -1;
  Vec3 barycentric{0.0};
  Vec3 target{0.0};
};

struct DeformationOptions {
  double mu = 1.0;  //!< weight of the position constraints (the paper's mu, Eq. 5-6)
};

//! Minimizes Eq. 5 (uniform Laplacian, Eq. 4: L(v) = v - mean of its 1-ring, the 1-ring taken from
//! the triangles) over the element's vertex positions and returns them (#V positions).
//! Several constraints may name the same vertex (an element with several partners collects them
//! all). Vertices in no triangle, and connected parts of the element that no constraint touches,
//! keep their positions (their energy is zero there). With no constraints the positions are
//! returned unchanged. Solved for the displacement by sparse normal equations (Eigen
//! SimplicialLDLT, one factorization shared by x, y and z).
//! \pre mu > 0; triangle indices in range.
//! \throw std::out_of_range for a constraint naming no vertex; InputError (invalid_option) for
//!        mu <= 0 or a non-finite target; SolverError when the factorization or solve fails.
std::vector<Vec3> deform_with_vertex_constraints(const TriMesh& element,
                                                 const std::vector<VertexConstraint>& constraints,
                                                 const DeformationOptions& options = {});

//! Minimizes Eq. 6 (constraints on barycentric combinations alpha w1 + beta w2 + gamma w3 of a
//! face's vertices, barycentrics normally summing to 1), otherwise as above.
//! \throw std::out_of_range for a constraint naming no face; InputError (invalid_option) for
//!        mu <= 0 or non-finite values; SolverError when the system is singular or the solve fails
//!        (e.g. barycentrics summing to 0 on an otherwise unconstrained part).
std::vector<Vec3> deform_with_face_constraints(const TriMesh& element,
                                               const std::vector<FaceConstraint>& constraints,
                                               const DeformationOptions& options = {});

}  // namespace meshquilt
