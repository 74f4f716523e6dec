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
  double mu = 1.0;  //!< weight of the position constraints
};

//! Minimizes Eq. 5 (uniform Laplacian, Eq. 4) over the element's vertex positions and returns them.
//! With no constraints the positions are returned unchanged. Solved by sparse normal equations
//! (Eigen SimplicialLDLT), one factorization per call.
//! \throw SolverError when the factorization or solve fails.
std::vector<Vec3> deform_with_vertex_constraints(const TriMesh& element,
                                                 const std::vector<VertexConstraint>& constraints,
                                                 const DeformationOptions& options = {});

//! Minimizes Eq. 6 (constraints on barycentric combinations of face vertices).
std::vector<Vec3> deform_with_face_constraints(const TriMesh& element,
                                               const std::vector<FaceConstraint>& constraints,
                                               const DeformationOptions& options = {});

}  // namespace meshquilt
