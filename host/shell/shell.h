#pragma once
//! The shell around a base mesh (Section 3.2 of the mesh quilting paper; Porumbescu et al. 2005):
//! the volume between the base and an offset surface, cut into prisms over the base faces and each
//! prism into three tetrahedra.
//!
//! Every base vertex moves along its own direction by its own height: its area-weighted vertex
//! normal, averaged with its neighbours' a few times, so that small dents of a scanned surface do
//! not turn the offsets toward each other, then turned back where it would lean over one of the
//! vertex's faces (sharp features), since no height makes such a prism stand. Heights
//! start at the shell height and are lowered where the shell would fold: where a tetrahedron of a
//! prism loses its volume (concave regions, sharp creases) and where the offset surface meets
//! itself or the base (thin parts). Lowered heights spread to neighbours with a slope limit, so
//! the offset surface stays smooth.

#include <array>
#include <cstdint>
#include <vector>

#include "surface/surface_types.h"

namespace meshquilt {

//! A corner of a prism: face corner `k` (0..2) on the base (top = 0) or the offset surface (1).
struct PrismCorner {
  uint8_t k = 0;
  uint8_t top = 0;
};
using PrismTet = std::array<PrismCorner, 4>;

//! The three tetrahedra of the prism over triangle `t`. The split depends only on the global
//! vertex indices: each side quad is cut by the diagonal from the lower index's base corner to the
//! higher index's top corner, so neighbouring prisms agree on their shared side. Every tetrahedron
//! has positive volume for a prism whose top lies above its counter-clockwise base.
std::array<PrismTet, 3> prism_tetrahedra(const Tri& t);

struct ShellOptions {
  double min_volume_share = 0.01;      //!< a tet must keep this share of its prism's nominal third
  double reduction = 0.7;              //!< factor applied to the heights of a failing prism
  double slope = 0.5;                  //!< most height change per unit of edge length
  double min_height_share = 1e-3;      //!< heights never go below this share of the shell height
  int direction_smoothing = 16;        //!< averaging passes over the vertex normals offsets follow
  double min_direction_cosine = 0.02;  //!< least cosine between a direction and its faces' normals
  int max_rounds = 40;
};

struct Shell {
  double height = 0.0;           //!< the shell height asked for
  std::vector<double> heights;   //!< #V offset distance of each base vertex (<= height)
  std::vector<Vec3> directions;  //!< #V unit offset directions (smoothed vertex normals)
  std::vector<Vec3> offset;      //!< #V offset-surface vertices
  int reduced_vertices = 0;      //!< vertices whose height was lowered
  int rounds = 0;                //!< validation rounds run
  int invalid_prisms = 0;        //!< prisms left with a tet of non-positive volume (0: valid)
  int offset_intersections = 0;  //!< offset face pairs left meeting each other or the base

  //! A prism corner of base face `f` in space.
  Vec3 corner(const Tri& t, PrismCorner c, const std::vector<Vec3>& base_positions) const {
    return c.top ? offset[t[c.k]] : base_positions[t[c.k]];
  }
};

//! Builds and validates the shell of `base` at `height` (base units, > 0). Validation uses exact
//! orientation tests for the tetrahedra and exact triangle tests (over an Embree BVH) for the
//! offset surface against itself and the base.
Shell build_shell(const BaseSurface& base, double height, const ShellOptions& options = {});

}  // namespace meshquilt
