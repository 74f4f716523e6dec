#pragma once
//! The triangle mesh every stage of meshquilt passes around: plain arrays, no connectivity cache.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace meshquilt {

using Vec3 = glm::dvec3;
using Tri = std::array<int32_t, 3>;

//! An indexed triangle mesh.
//! positions  #V vertex positions
//! triangles  #F vertex indices, counter-clockwise seen from outside
//! elements   #F element id per face, or empty when not known (elements are then the
//!            vertex-connected components, see topology.h)
//! sources    #F index of the swatch element each face was copied from, or empty (quilted
//!            outputs carry it, so the wefts of a weave can be told from its warps)
struct TriMesh {
  std::vector<Vec3> positions;
  std::vector<Tri> triangles;
  std::vector<int32_t> elements;
  std::vector<int32_t> sources;

  size_t num_vertices() const { return positions.size(); }
  size_t num_faces() const { return triangles.size(); }
};

}  // namespace meshquilt
