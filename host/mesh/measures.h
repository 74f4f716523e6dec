#pragma once
//! Measures of a triangle mesh read from its positions: edge lengths and vertex normals.

#include <limits>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Mean edge length over all face edges, each face counting its three edges (an edge shared by
//! two faces counts twice); 0 for a mesh without faces.
//! \pre indices in range.
double mean_edge_length(const TriMesh& mesh);

//! Area-weighted unit vertex normals: #V, the normalized sum of the cross products (twice the
//! areas) of the faces around each vertex; `without_area` where that sum is zero (no face, or only
//! degenerate or cancelling ones, meet at the vertex).
//! \pre indices in range.
std::vector<Vec3> vertex_normals(const TriMesh& mesh, const Vec3& without_area);

//! An axis-aligned box; empty (lo > hi) when it holds no point.
struct Box3 {
  Vec3 lo{std::numeric_limits<double>::max()};
  Vec3 hi{std::numeric_limits<double>::lowest()};
  Vec3 extent() const { return hi - lo; }
  bool overlaps(const Box3& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y && lo.z <= o.hi.z && o.lo.z <= hi.z;
  }
};

//! Bounding box of points.
Box3 bounding_box(const std::vector<Vec3>& points);

//! vertex_normals with (0,0,1) for a vertex without area: the up direction of a swatch.
std::vector<Vec3> vertex_normals(const TriMesh& mesh);

}  // namespace meshquilt
