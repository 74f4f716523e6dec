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

//! Half the cotangent of the angle at corner k of t: the cotangent Laplacian's weight of the edge
//! opposite it, from this face. Capped at 500 either way for slivers; 0 for a degenerate corner.
double half_cotangent(const TriMesh& mesh, const Tri& t, int k);

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

//! A sphere holding a face: its centroid and the distance to its farthest corner, padded (by
//! 1e-12 relative) so that rounding never leaves a point of the face outside. The gap
//! max(|p - centre| - radius, 0) is then a quick lower bound of the distance from p to the face.
struct FaceSphere {
  Vec3 centre{0.0};
  double radius = 0.0;
};

//! One sphere per face (#F). \pre indices in range.
std::vector<FaceSphere> face_spheres(const TriMesh& mesh);

//! A face's plane: its unit normal ((0,0,1) where the cross product of its edges vanishes) and
//! whether the plane's distance bounds the face's from below (`planar`: twice the area above
//! 1e-6 of the longest edge squared; a sliver's normal is too uncertain for that).
struct FacePlane {
  Vec3 normal{0.0, 0.0, 1.0};
  bool planar = false;
};

//! One plane per face (#F). \pre indices in range.
std::vector<FacePlane> face_planes(const TriMesh& mesh);

//! vertex_normals with (0,0,1) for a vertex without area: the up direction of a swatch.
std::vector<Vec3> vertex_normals(const TriMesh& mesh);

}  // namespace meshquilt
