#include "spatial/intersecting_pairs.h"

#include <algorithm>
#include <string>

#include <tbb/enumerable_thread_specific.h>

#include "core/error.h"
#include "spatial/face_bvh.h"
#include "spatial/triangle_intersection.h"

namespace meshquilt {
namespace {

bool share_vertex(const Tri& a, const Tri& b) {
  for (int32_t u : a) {
    if (u == b[0] || u == b[1] || u == b[2]) return true;
  }
  return false;
}

void sort_merged(tbb::enumerable_thread_specific<std::vector<FacePair>>& parts, std::vector<FacePair>& out) {
  for (auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  std::sort(out.begin(), out.end());
}

FaceIntersections find(const TriMesh& mesh, const std::vector<int32_t>& face_element, bool want_different,
                       bool want_same) {
  if (face_element.size() != mesh.num_faces()) {
    throw InputError("intersecting faces: " + std::to_string(face_element.size()) + " element ids for " +
                     std::to_string(mesh.num_faces()) + " faces");
  }
  FaceIntersections result;
  if (mesh.num_faces() < 2) return result;
  tbb::enumerable_thread_specific<std::vector<FacePair>> different, same;
  const FaceBvh bvh(mesh, BvhQuality::low);
  // Embree runs the collision on its own worker threads; each collects into its own list.
  bvh.for_each_overlapping_pair([&](int32_t f, int32_t g) {
    const Tri& a = mesh.triangles[f];
    const Tri& b = mesh.triangles[g];
    const bool same_element = face_element[f] == face_element[g];
    if (same_element ? (!want_same || share_vertex(a, b)) : !want_different) return;
    const auto& x = mesh.positions;
    if (triangles_intersect(x[a[0]], x[a[1]], x[a[2]], x[b[0]], x[b[1]], x[b[2]])) {
      (same_element ? same : different).local().emplace_back(f, g);
    }
  });
  sort_merged(different, result.different_elements);
  sort_merged(same, result.same_element);
  return result;
}

}  // namespace

FaceIntersections find_intersecting_faces(const TriMesh& mesh, const std::vector<int32_t>& face_element) {
  return find(mesh, face_element, true, true);
}

std::vector<FacePair> intersecting_face_pairs(const TriMesh& mesh, const std::vector<int32_t>& face_element,
                                              IntersectionScope scope) {
  const bool different = scope == IntersectionScope::different_elements;
  FaceIntersections r = find(mesh, face_element, different, !different);
  return different ? std::move(r.different_elements) : std::move(r.same_element);
}

}  // namespace meshquilt
