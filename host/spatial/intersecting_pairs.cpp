#include "spatial/intersecting_pairs.h"

#include <algorithm>
#include <string>

#include <glm/common.hpp>

#include <tbb/enumerable_thread_specific.h>

#include "core/error.h"
#include "mesh/measures.h"
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

FaceIntersections find_intersecting_faces_again(const TriMesh& mesh, const std::vector<int32_t>& face_element,
                                                const FaceIntersections& before, const std::vector<uint8_t>& moved) {
  if (face_element.size() != mesh.num_faces()) return find_intersecting_faces(mesh, face_element);
  const auto is_moved = [&](int32_t e) { return e >= 0 && static_cast<size_t>(e) < moved.size() && moved[e]; };
  // Bounds of each element, and of the moved ones together.
  std::vector<Box3> bounds;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const int32_t e = face_element[f];
    if (e < 0) continue;
    if (static_cast<size_t>(e) >= bounds.size()) bounds.resize(e + 1);
    for (int32_t v : mesh.triangles[f]) {
      bounds[e].lo = glm::min(bounds[e].lo, mesh.positions[v]);
      bounds[e].hi = glm::max(bounds[e].hi, mesh.positions[v]);
    }
  }
  std::vector<uint8_t> near(bounds.size(), 0);
  for (size_t m = 0; m < bounds.size(); ++m) {
    if (!is_moved(static_cast<int32_t>(m))) continue;
    for (size_t e = 0; e < bounds.size(); ++e)
      if (!near[e] && bounds[e].overlaps(bounds[m])) near[e] = 1;
  }
  // Those faces alone, with the vertices they use.
  TriMesh part;
  std::vector<int32_t> part_face, part_element;
  std::vector<int32_t> vertex(mesh.num_vertices(), -1);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const int32_t e = face_element[f];
    if (e < 0 || !near[e]) continue;
    Tri t;
    for (int k = 0; k < 3; ++k) {
      int32_t& v = vertex[mesh.triangles[f][k]];
      if (v < 0) {
        v = static_cast<int32_t>(part.positions.size());
        part.positions.push_back(mesh.positions[mesh.triangles[f][k]]);
      }
      t[k] = v;
    }
    part.triangles.push_back(t);
    part_face.push_back(static_cast<int32_t>(f));
    part_element.push_back(e);
  }
  const FaceIntersections found = find_intersecting_faces(part, part_element);
  FaceIntersections result;
  const auto merge = [&](const std::vector<FacePair>& old_pairs, const std::vector<FacePair>& new_pairs,
                         std::vector<FacePair>& out) {
    for (const auto& [f, g] : old_pairs)
      if (!is_moved(face_element[f]) && !is_moved(face_element[g])) out.emplace_back(f, g);
    for (const auto& [a, b] : new_pairs) {
      const int32_t f = part_face[a], g = part_face[b];
      if (is_moved(face_element[f]) || is_moved(face_element[g])) out.emplace_back(std::min(f, g), std::max(f, g));
    }
    std::sort(out.begin(), out.end());
  };
  merge(before.different_elements, found.different_elements, result.different_elements);
  merge(before.same_element, found.same_element, result.same_element);
  return result;
}

std::vector<FacePair> intersecting_face_pairs(const TriMesh& mesh, const std::vector<int32_t>& face_element,
                                              IntersectionScope scope) {
  const bool different = scope == IntersectionScope::different_elements;
  FaceIntersections r = find(mesh, face_element, different, !different);
  return different ? std::move(r.different_elements) : std::move(r.same_element);
}

}  // namespace meshquilt
