#pragma once
//! Lattice fill: over a layout whose seams continue by a repeating swatch's periods, the
//! pattern's elements that stand alone (quilt/lattice_classes.h) are placed straight from layout
//! windows, one at each period, away from the layout's cones and the base's borders. They are
//! what the patch step would place there (lattice copies of each other, paired with nothing), so
//! the step only quilts where the pattern breaks.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "quilt/lattice_classes.h"
#include "quilt/plane_rect.h"
#include "quilt/quilt_swatch.h"
#include "quilt/swatch_lattice.h"
#include "surface/conformal_patch.h"
#include "surface/surface_types.h"

namespace meshquilt {

//! How far each base vertex lies from the nearest of `points` (a face holding each, and where)
//! or from the base's border, along edges: where the pattern breaks.
std::vector<double> distance_to_breaks(const BaseSurface& base,
                                       const std::vector<std::pair<int32_t, Vec3>>& points);

//! A swatch element placed over the base; the n-th placed is element n of the fill.
struct FilledElement {
  int32_t source = -1;                //!< the swatch element it copies
  std::vector<LocalVertex> vertices;  //!< in the order of the swatch element's
};

//! What one window placed, and where the pattern is whole in it.
struct FilledWindow {
  std::vector<FilledElement> added;  //!< elements no earlier window placed
  //! Plane bounds of the pattern's elements now over the base, and which element of the fill each is.
  std::vector<std::pair<Rect2, int32_t>> present;
  std::vector<Rect2> absent;  //!< plane bounds of those this window could not place
  //! Whether a kept element (`kept`, by element of the fill) is over the base at `p` and none is
  //! missing within `margin` of it.
  bool covers(const glm::dvec2& p, double margin, const std::vector<uint8_t>& kept) const;
};

class LatticeFill {
 public:
  //! unit: base units per swatch unit in the plane; height_unit: per swatch z. `base`, `swatch`
  //! and `lattice` outlive this object.
  LatticeFill(const BaseSurface& base, const QuiltSwatch& swatch, const SwatchLattice& lattice,
              std::vector<LatticeClass> classes, std::vector<double> break_distance, double margin,
              double unit, double height_unit);

  //! Some class stands alone: there is something to fill.
  bool any() const;
  //! Places the pattern over a layout window (in swatch units, transformed and indexed): every
  //! element of a class that stands alone, at every period where it lies wholly in the window,
  //! farther than the margin from a break and unplaced before.
  FilledWindow fill(const SurfacePatch& window, const glm::dvec2& shift);
  int filled() const { return filled_; }
  //! Within the margin of a cone or the border.
  bool near_break(const SurfacePoint& p) const;

 private:
  struct Key {
    int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const;
  };
  int32_t placed_before(const Vec3& centre) const;  // the element there, or -1

  const BaseSurface& base_;
  const QuiltSwatch& swatch_;
  const SwatchLattice& lattice_;
  std::vector<LatticeClass> classes_;
  std::vector<double> class_height_;    // mean z of each class's element
  std::vector<Rect2> class_bounds_;     // x-y bounds of each class's element
  std::vector<double> break_distance_;  // per base vertex
  double margin_, unit_, height_unit_, bucket_;
  // The centre of each placed element, and which it is.
  std::unordered_map<Key, std::vector<std::pair<Vec3, int32_t>>, KeyHash> placed_;
  int filled_ = 0;
};

}  // namespace meshquilt
