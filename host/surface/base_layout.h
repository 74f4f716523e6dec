#pragma once
//! The shared layout of a base as the surface driver uses it: the smoothest n-direction field
//! holding the guidance field's given directions (where none were drawn on a closed genus-0
//! base or a disc, the cone metric's field, with pairs of cones where its scale runs away, unless it
//! spreads more: cone_metric_field.h), and the
//! seamless layout that follows it
//! (seamless_layout.h), computed over the base split 1-to-4 where it is coarse. A field's cones
//! need room: on the 320 faces of `data/sphere.off` the smoothest line field has two index-1
//! singularities, around which no layout opens without folding; split once, four of index 1/2.

#include <cstdint>
#include <memory>
#include <vector>

#include "surface/cone_metric_field.h"
#include "surface/seamless_layout.h"

namespace meshquilt {

class BaseLayout {
 public:
  //! target, weight: per base face, as smoothest_direction_field takes them; drawn: the user
  //! gave directions, which the field must follow; lattice, size_hold: as seamless_layout
  //! takes them; cone_spread: the bound on the cone metric's scale spread (ConeBound::spread);
  //! stand_alone: the pattern's elements stand alone (rings); else they run on (yarns), end at
  //! every cone, and each cone more than the smoothest field has must narrow the spread.
  //! \throw SolverError when a solve fails.
  BaseLayout(const BaseSurface& base, int symmetry, const std::vector<Vec3>& target, const std::vector<double>& weight,
             bool drawn = false, const std::optional<std::array<glm::dvec2, 2>>& lattice = std::nullopt,
             double size_hold = kDefaultSizeHold, double cone_spread = kDefaultConeSpread, bool stand_alone = true);
  //! Lays the same field out again with elements element_scale times the size (seamless_layout).
  void resize(double element_scale);
  BaseLayout(const BaseLayout&) = delete;
  BaseLayout& operator=(const BaseLayout&) = delete;

  //! A window of the layout over base faces (a face-connected set holding `start`): its corners'
  //! plane coordinates at the base's vertices; face_turn per base face (that of its first part).
  //! corner_vertex  3 x #faces local vertex index of each corner; vertices: the number of them
  LayoutWindow unfold(const std::vector<int32_t>& faces, int32_t start, const std::vector<int32_t>& corner_vertex,
                      int32_t vertices) const;

  //! The layout's u direction on a base face (that of its first part).
  Vec3 axis(int32_t base_face) const { return layout_.axis[first_part(base_face)]; }
  int symmetry() const { return layout_.symmetry; }
  int cones() const { return static_cast<int>(layout_.cones.size()); }
  //! scale_spread of the flat metric with the field's cones; 0 where not known (a drawn field, a
  //! base that is neither one closed sphere nor one disc).
  double scale_spread() const { return scale_spread_; }
  //! Where the cones are: a base face holding each and its point in space.
  std::vector<std::pair<int32_t, Vec3>> cone_points() const;
  int levels() const { return levels_; }           //!< times the base was split 1-to-4
  const SeamlessLayout& layout() const { return layout_; }

 private:
  int32_t first_part(int32_t base_face) const { return base_face << (2 * levels_); }

  const BaseSurface& base_;
  int levels_ = 0;
  TriMesh fine_mesh_;
  std::unique_ptr<BaseSurface> fine_;
  DirectionField field_;
  std::optional<std::array<glm::dvec2, 2>> lattice_;
  double size_hold_;
  double scale_spread_ = 0.0;
  SeamlessLayout layout_;
};

//! The mesh split 1-to-4 (edge midpoints) `levels` times: the same surface; the first vertices
//! are the mesh's own, and the parts of face f are faces f x 4^levels to (f + 1) x 4^levels - 1.
TriMesh split_faces(const TriMesh& mesh, int levels);

}  // namespace meshquilt
