#include "quilt/lattice_classes.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "mesh/measures.h"
#include "quilt/lattice_copies.h"
#include "quilt/plane_rect.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {

glm::dvec2 centroid_of(const TriMesh& mesh) {
  glm::dvec2 sum(0.0);
  for (const Vec3& p : mesh.positions) sum += glm::dvec2(p);
  return mesh.positions.empty() ? sum : sum / static_cast<double>(mesh.positions.size());
}

// The period d with a + d = b, where b - a lies within `tolerance` of one.
bool period_between(const glm::dvec2& a, const glm::dvec2& b, const std::array<glm::dvec2, 2>& basis,
                    double tolerance, glm::dvec2& d) {
  d = nearest_period(b - a, basis);
  return glm::distance(b - a, d) <= tolerance;
}

}  // namespace

std::vector<LatticeClass> lattice_classes(const QuiltSwatch& swatch, const SwatchLattice& lattice,
                                          double partner_distance, double tolerance) {
  const std::array<glm::dvec2, 2>& basis = lattice.basis;
  std::vector<LatticeClass> classes;
  std::vector<uint8_t> clash;  // another class lies at the same place
  for (size_t k = 0; k < swatch.elements.size(); ++k) {
    const glm::dvec2 c = centroid_of(swatch.elements[k]);
    int32_t member = -1;
    bool clashes = false;  // an element of another shape lies at the same place
    for (size_t j = 0; j < classes.size() && member < 0; ++j) {
      glm::dvec2 d;
      if (!period_between(classes[j].centroid, c, basis, tolerance, d)) continue;
      if (same_element(swatch.elements[k], swatch.elements[classes[j].element], tolerance, Vec3(d, 0.0))) {
        member = static_cast<int32_t>(j);
      } else {
        clash[j] = 1;
        clashes = true;
      }
    }
    if (member >= 0) {
      if (clashes) clash[member] = 1;
      continue;
    }
    classes.push_back({static_cast<int32_t>(k), c, false});
    clash.push_back(clashes);
  }
  // Which pairs to test: those whose bounds, the one moved by a period, come within reach.
  const double reach = partner_distance;
  const double shortest = std::min(glm::length(basis[0]), glm::length(basis[1]));
  std::vector<Rect2> bounds;
  std::vector<std::unique_ptr<FaceBvh>> faces;
  std::vector<std::vector<Vec3>> normals;
  std::vector<std::vector<FacePlane>> planes;
  double widest = 0.0;
  for (const LatticeClass& c : classes) {
    const TriMesh& element = swatch.elements[c.element];
    bounds.push_back(swatch.element_bounds[c.element]);
    faces.push_back(std::make_unique<FaceBvh>(element));
    normals.push_back(vertex_normals(element));
    planes.push_back(face_planes(element));
    widest = std::max(widest, glm::length(bounds.back().hi - bounds.back().lo));
  }
  // As the step relates an output element to an input (correspondence.h): each vertex to the
  // nearest face within the pairing range whose normal does not oppose its own; partners where
  // the mean distance of those pairs is within reach.
  const double pairing = 3.0 * swatch.mean_edge;
  const auto partners = [&](size_t a, size_t b, const glm::dvec2& q) {
    const TriMesh& from = swatch.elements[classes[a].element];
    double sum = 0.0;
    int count = 0;
    for (size_t v = 0; v < from.positions.size(); ++v) {
      const ClosestPoint c = faces[b]->closest_point(from.positions[v] + Vec3(q, 0.0), pairing);
      if (c.face < 0 || glm::dot(planes[b][c.face].normal, normals[a][v]) < 0.0) continue;
      sum += c.distance;
      ++count;
    }
    return count > 0 && sum <= reach * count;
  };
  // Periods further apart than two of the widest elements cannot bring two together.
  const int64_t range = static_cast<int64_t>(std::ceil((widest + pairing) / shortest)) + 1;
  for (size_t a = 0; a < classes.size(); ++a) {
    bool alone = !clash[a] && range <= 64;
    for (size_t b = 0; b < classes.size() && alone; ++b)
      for (int64_t ky = -range; ky <= range && alone; ++ky)
        for (int64_t kx = -range; kx <= range && alone; ++kx) {
          if (a == b && kx == 0 && ky == 0) continue;
          const glm::dvec2 q = static_cast<double>(kx) * basis[0] + static_cast<double>(ky) * basis[1];
          const Rect2 moved{bounds[a].lo + q - pairing, bounds[a].hi + q + pairing};
          if (!moved.overlaps(bounds[b])) continue;
          if (partners(a, b, q) || partners(b, a, -q)) alone = false;
        }
    classes[a].alone = alone;
  }
  return classes;
}

}  // namespace meshquilt
