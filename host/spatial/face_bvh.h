#pragma once
//! Embree-backed spatial queries over the faces of one triangle mesh. The only place in
//! meshquilt that includes Embree.

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.h"
#include "spatial/closest_point.h"

namespace meshquilt {

//! The face a ray meets first and where along the ray.
struct RayHit {
  int32_t face = -1;  //!< -1: the ray meets no face within its range
  double distance = std::numeric_limits<double>::infinity();  //!< ray parameter t of the hit
};

//! Where the ray origin + t * direction meets triangle (a, b, c) for t > 0, two-sided
//! (Moller-Trumbore in double; points on an edge count as inside, a ray in the triangle's plane
//! misses). Returns t, or +infinity on a miss.
double ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b, const Vec3& c);

//! Embree build quality: `low` builds fastest (one-shot pair searches), `medium` gives faster
//! point queries (many queries against one BVH).
enum class BvhQuality { low, medium };

//! A BVH over a mesh's faces. The mesh must outlive the BVH and not change. Queries are exact in
//! double precision (Embree's float BVH only prunes, with a conservative margin) and may run
//! concurrently from several threads. Faces are an Embree user geometry whose boxes come from
//! the double positions rounded outward, so Embree holds no float copy of the vertices (and no
//! padded vertex buffer is needed). Ties between equally close faces go to the lower index.
//! Construction throws DeviceError when Embree cannot start (unsupported CPU, out of memory) and
//! SolverError for any other Embree error.
class FaceBvh {
 public:
  explicit FaceBvh(const TriMesh& mesh, BvhQuality quality = BvhQuality::medium);
  //! A BVH over the listed faces of `mesh` only; answers name faces of `mesh`, and ties still go
  //! to the lower face index of `mesh`.
  //! \throw std::out_of_range for a face outside the mesh.
  FaceBvh(const TriMesh& mesh, std::vector<int32_t> faces, BvhQuality quality = BvhQuality::medium);
  ~FaceBvh();
  FaceBvh(const FaceBvh&) = delete;
  FaceBvh& operator=(const FaceBvh&) = delete;

  //! Closest point on any face within max_distance (radius-shrinking rtcPointQuery).
  ClosestPoint closest_point(const Vec3& p, double max_distance = std::numeric_limits<double>::infinity()) const;

  //! The face minimizing cost(face, closest point on it). radius_for(best_cost) must return a
  //! distance beyond which no face can beat best_cost (e.g. (D - 1) / lambda for Eq. 1), so the
  //! search radius shrinks as better faces are found; the answer is exact. `best_cost` receives
  //! the minimum (infinity when the mesh is empty).
  //! Among faces of equal cost the lowest index wins. `known_cost`, when finite, is a cost
  //! face `known_face` (or some face, when -1) is known to reach: the search then starts at
  //! radius_for(known_cost), and when no face beats it (costs less, or as much with a lower
  //! index than `known_face`) the answer has face -1 and `best_cost` = known_cost. `face_bound`,
  //! when given, is a cheap lower bound of a face's cost (without its closest point): a face
  //! whose bound exceeds the best so far is passed over. With `offset`, the faces are taken moved
  //! by it: closest points are measured to the corners positions[v] + offset (the arithmetic of a
  //! moved copy of the mesh, so the answer is that copy's BVH's), and the BVH is searched around
  //! p - offset.
  ClosestPoint min_cost_face(const Vec3& p,
                             const std::function<double(const ClosestPoint&)>& cost,
                             const std::function<double(double best_cost)>& radius_for,
                             double* best_cost,
                             double known_cost = std::numeric_limits<double>::infinity(),
                             const std::function<double(int32_t face)>& face_bound = {},
                             int32_t known_face = -1, const Vec3& offset = Vec3(0.0)) const;

  //! The first face met by the ray origin + t * direction, 0 < t <= max_distance, both sides of a
  //! face counting; `distance` is t (the Euclidean distance when direction has unit length).
  //! Each candidate is tested exactly in double (ray_triangle); ties go to the lower face index.
  //! Embree's float traversal may still skip a face that the ray only grazes within float
  //! rounding of its bounding box, which for rendering can only swap an edge pixel's face with
  //! its neighbour. \pre direction is not zero. \throw SolverError when Embree reports an error.
  RayHit ray_cast(const Vec3& origin, const Vec3& direction,
                  double max_distance = std::numeric_limits<double>::infinity()) const;

  //! Faces whose bounding boxes overlap the box [lo, hi] (appended to `faces`, unordered).
  void faces_in_box(const Vec3& lo, const Vec3& hi, std::vector<int32_t>& faces) const;

  //! Calls visit(f, g) once for every pair of faces f < g whose (double) bounding boxes overlap
  //! (closed boxes: touching counts), using Embree's BVH-against-BVH collision. visit may be
  //! called concurrently from several threads and must be thread-safe.
  //! \throw DeviceError or SolverError when Embree reports an error.
  void for_each_overlapping_pair(const std::function<void(int32_t, int32_t)>& visit) const;

  const TriMesh& mesh() const { return mesh_; }

 private:
  FaceBvh(const TriMesh& mesh, std::vector<int32_t> faces, bool subset, BvhQuality quality);
  struct Impl;
  const TriMesh& mesh_;
  size_t primitives_ = 0;  // faces in the BVH
  std::unique_ptr<Impl> impl_;
};

}  // namespace meshquilt
