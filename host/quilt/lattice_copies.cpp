#include "quilt/lattice_copies.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_precision.hpp>

#include "mesh/measures.h"
#include "quilt/plane_rect.h"
#include "spatial/face_bvh.h"
#include "quilt/swatch_lattice.h"

namespace meshquilt {
namespace {

bool near(const Vec3& a, const Vec3& b, double tolerance) {
  return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

bool near(const Rect2& a, const Rect2& b, double tolerance) {
  return std::abs(a.lo.x - b.lo.x) <= tolerance && std::abs(a.lo.y - b.lo.y) <= tolerance &&
         std::abs(a.hi.x - b.hi.x) <= tolerance && std::abs(a.hi.y - b.hi.y) <= tolerance;
}

}  // namespace

bool same_element(const TriMesh& a, const TriMesh& b, double tolerance, const Vec3& offset) {
  if (a.triangles.size() != b.triangles.size() || a.positions.size() != b.positions.size()) return false;
  // A part collected from a surface numbers its vertices as its faces first use them.
  std::vector<int32_t> to_b(a.positions.size(), -1), to_a(b.positions.size(), -1);
  for (size_t f = 0; f < a.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t va = a.triangles[f][k], vb = b.triangles[f][k];
      if (to_b[va] < 0 && to_a[vb] < 0) {
        if (!near(a.positions[va], b.positions[vb] + offset, tolerance)) return false;
        to_b[va] = vb;
        to_a[vb] = va;
      } else if (to_b[va] != vb || to_a[vb] != va) {
        return false;
      }
    }
  return true;
}

std::vector<int32_t> lattice_copies(const std::vector<PlaneElement>& layer, const std::vector<int32_t>& candidates,
                                    const std::vector<TriMesh>& inputs, double tolerance) {
  std::vector<int32_t> copy_of(inputs.size(), -1);
  std::vector<uint8_t> taken(candidates.size(), 0);
  for (size_t i = 0; i < inputs.size(); ++i) {
    const Rect2 bounds = xy_bounds(inputs[i]);
    for (size_t c = 0; c < candidates.size(); ++c) {
      const PlaneElement& e = layer[candidates[c]];
      if (taken[c] || !e.alive || !e.pinned.empty() || !near(e.bounds, bounds, tolerance)) continue;
      if (!same_element(inputs[i], e.mesh, tolerance)) continue;
      copy_of[i] = candidates[c];
      taken[c] = 1;
      break;
    }
  }
  return copy_of;
}

namespace {

// Whether `mesh` is swatch element `source` moved in x-y by `translation` and a period; that
// period's lattice coordinates go to `k`.
bool pattern_copy(const TriMesh& mesh, const TriMesh& source, const glm::dvec2& translation,
                  const std::array<glm::dvec2, 2>& periods, double tolerance, glm::i64vec2& k) {
  if (mesh.triangles.empty() || mesh.triangles.size() != source.triangles.size()) return false;
  const Vec3 d = mesh.positions[mesh.triangles[0][0]] - source.positions[source.triangles[0][0]];
  const glm::dvec2 shift = glm::dvec2(d.x, d.y) - translation;
  const glm::dvec2 period = nearest_period(shift, periods);
  if (glm::distance(shift, period) > tolerance) return false;
  if (!same_element(mesh, source, tolerance, Vec3(d.x, d.y, 0.0))) return false;
  k = glm::i64vec2(glm::round(lattice_coordinates(period, periods)));
  return true;
}

}  // namespace

struct LatticeContacts::Faces {
  explicit Faces(const TriMesh& mesh) : bounds(bounding_box(mesh.positions)), bvh(mesh) {}
  Box3 bounds;
  FaceBvh bvh;
};

LatticeContacts::LatticeContacts(const QuiltSwatch& swatch, const std::array<glm::dvec2, 2>& periods, double reach)
    : swatch_(swatch), periods_(periods), reach_(reach), faces_(swatch.elements.size()) {}

LatticeContacts::~LatticeContacts() = default;

bool LatticeContacts::touches(int32_t a, int32_t b, const glm::i64vec2& k) {
  const Key key{a, b, k.x, k.y};
  if (const auto it = known_.find(key); it != known_.end()) return it->second;
  if (!faces_[b]) faces_[b] = std::make_unique<Faces>(swatch_.elements[b]);
  const Faces& to = *faces_[b];
  const glm::dvec2 q = static_cast<double>(k.x) * periods_[0] + static_cast<double>(k.y) * periods_[1];
  const Vec3 offset(q, 0.0);
  bool near_b = false;
  for (const Vec3& v : swatch_.elements[a].positions) {
    const Vec3 p = v + offset;
    if (glm::any(glm::lessThan(p, to.bounds.lo - Vec3(reach_))) || glm::any(glm::greaterThan(p, to.bounds.hi + Vec3(reach_))))
      continue;
    if (to.bvh.closest_point(p, reach_).face >= 0) {
      near_b = true;
      break;
    }
  }
  known_.emplace(key, near_b);
  return near_b;
}

std::vector<uint8_t> lattice_neighbours(const std::vector<PlaneElement>& layer, const std::vector<int32_t>& candidates,
                                        const std::vector<int32_t>& input_sources, const QuiltSwatch& swatch,
                                        const glm::dvec2& translation, LatticeContacts& contacts, double tolerance) {
  std::vector<uint8_t> neighbour(candidates.size(), 0);
  for (size_t c = 0; c < candidates.size(); ++c) {
    const PlaneElement& e = layer[candidates[c]];
    if (!e.alive || !e.pinned.empty() || e.source < 0 || e.source >= static_cast<int32_t>(swatch.elements.size()))
      continue;
    glm::i64vec2 k;
    if (!pattern_copy(e.mesh, swatch.elements[e.source], translation, contacts.periods(), tolerance, k)) continue;
    neighbour[c] = std::none_of(input_sources.begin(), input_sources.end(),
                                [&](int32_t b) { return contacts.touches(e.source, b, k); });
  }
  return neighbour;
}

}  // namespace meshquilt
