#pragma once
//! The types every surface stage shares (Section 3 of the mesh quilting paper): points on the
//! base, the base with what patches need of it, and output vertices in local coordinates.

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A point on the base: a face and the barycentrics of the point in it (b0 = 1 - b1 - b2).
struct SurfacePoint {
  int32_t face = -1;
  glm::dvec2 bary{0.0};  //!< (b1, b2)
};

//! What patches need of a base mesh, computed once.
struct BaseSurface {
  explicit BaseSurface(const TriMesh& base);
  const TriMesh& mesh;
  std::vector<Vec3> vertex_normals;                             //!< #V, area weighted, unit
  std::vector<Vec3> face_normals;                               //!< #F, unit (0 for a degenerate face)
  std::vector<double> face_areas;                               //!< #F
  std::vector<std::vector<int32_t>> vertex_faces;               //!< #V, faces around each vertex
  std::vector<std::array<int32_t, 3>> face_across;              //!< #F, as face_neighbors gives them
  std::vector<std::vector<std::pair<int32_t, double>>> edges;  //!< #V, (neighbour, edge length)
  double area = 0.0;                                            //!< total area
  double diagonal = 0.0;                                        //!< bounding-box diagonal

  Vec3 position(const SurfacePoint& p) const;  //!< the point in space
  Vec3 normal(const SurfacePoint& p) const;    //!< interpolated vertex normal, unit
};

//! An output vertex in local coordinates: a base point and its height above it (base units).
struct LocalVertex {
  SurfacePoint point;
  double height = 0.0;
};

}  // namespace meshquilt
