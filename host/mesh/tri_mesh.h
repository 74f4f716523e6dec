#pragma once
//! The triangle mesh every stage of meshquilt passes around: plain arrays, no connectivity cache.

#include <array>
#include <cstdint>
#include <functional>
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
//! colors     #V RGB per vertex, or empty (set by `meshquilt edit`; PLY and glTF keep them)
//! origins    #V index of the swatch vertex (in the swatch file's order) each vertex was copied
//!            from, or empty: carried through deformation, merging and stitching (a seam vertex
//!            welded from two takes the first part's), so swatch animations can follow it
struct TriMesh {
  std::vector<Vec3> positions;
  std::vector<Tri> triangles;
  std::vector<int32_t> elements;
  std::vector<int32_t> sources;
  std::vector<std::array<uint8_t, 3>> colors;
  std::vector<int32_t> origins;

  size_t num_vertices() const { return positions.size(); }
  size_t num_faces() const { return triangles.size(); }
};

//! Hash of a position's exact bits, for finding vertices that did not move (equal doubles).
struct ExactPositionHash {
  size_t operator()(const Vec3& p) const {
    const std::hash<double> h;
    return h(p.x) ^ (h(p.y) * 0x9e3779b97f4a7c15ull) ^ (h(p.z) * 0xc2b2ae3d27d4eb4full);
  }
};

}  // namespace meshquilt
