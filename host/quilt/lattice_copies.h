#pragma once
//! Lattice copies: a swatch element placed where the output already holds the same element (a
//! repeating swatch placed at one of its periods over a layer laid on the same lattice). Such an
//! input is the element already there: it needs no correspondence, deformation or cut, since the
//! full step would pair every vertex at distance zero, deform nothing and merge the two into the
//! one they already are.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include <glm/gtc/type_precision.hpp>

#include "mesh/tri_mesh.h"
#include "quilt/patch_step.h"

namespace meshquilt {

//! Whether `a` and `b` moved by `offset` are one element: the same triangles in the same order, up
//! to a renumbering of vertices, and each vertex of `a` within `tolerance` of its vertex of `b`
//! (in every axis).
bool same_element(const TriMesh& a, const TriMesh& b, double tolerance, const Vec3& offset = Vec3(0.0));

//! For each input, the alive, whole (unpinned) layer element among `candidates` that it is
//! (same_element), or -1. Each layer element stands for at most one input.
std::vector<int32_t> lattice_copies(const std::vector<PlaneElement>& layer, const std::vector<int32_t>& candidates,
                                    const std::vector<TriMesh>& inputs, double tolerance);

//! Which elements of a repeating swatch's pattern come near each other: whether swatch element
//! `a` moved by a period q has a vertex within `reach` of a face of element `b`, answered once
//! per (a, b, q) and kept. `reach` is the partner distance: an output element none of whose
//! vertices comes that near an input's faces can pair with it at no smaller mean distance, so
//! the full step would never make them partners, deform it or cut it.
class LatticeContacts {
 public:
  //! `swatch` outlives this object.
  LatticeContacts(const QuiltSwatch& swatch, const std::array<glm::dvec2, 2>& periods, double reach);
  ~LatticeContacts();
  LatticeContacts(const LatticeContacts&) = delete;
  LatticeContacts& operator=(const LatticeContacts&) = delete;

  const std::array<glm::dvec2, 2>& periods() const { return periods_; }
  //! Whether element `a` moved by k.x periods[0] + k.y periods[1] comes within reach of `b`.
  bool touches(int32_t a, int32_t b, const glm::i64vec2& k);

 private:
  struct Faces;
  const QuiltSwatch& swatch_;
  std::array<glm::dvec2, 2> periods_;
  double reach_;
  std::vector<std::unique_ptr<Faces>> faces_;  // per swatch element, built when first asked
  using Key = std::tuple<int32_t, int32_t, int64_t, int64_t>;  // a, b, k
  std::map<Key, bool> known_;
};

//! For each of `candidates`, 1 where the layer element is an unchanged copy of its swatch element
//! (`source`) at `translation` moved by a period (within `tolerance`) that comes within reach of
//! none of the swatch elements `input_sources` placed at `translation` (contacts.touches): another
//! element of the pattern, which the step would leave as it is.
std::vector<uint8_t> lattice_neighbours(const std::vector<PlaneElement>& layer, const std::vector<int32_t>& candidates,
                                        const std::vector<int32_t>& input_sources, const QuiltSwatch& swatch,
                                        const glm::dvec2& translation, LatticeContacts& contacts, double tolerance);

}  // namespace meshquilt
