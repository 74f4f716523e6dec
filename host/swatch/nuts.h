#pragma once
//! Hex-nut swatches: hexagonal prisms with a round hole (genus 1), lying flat in one layer at
//! varied rotations about z, without touching.

#include <cstdint>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Count, size and tessellation of a nut swatch. Each nut is one closed quad grid (split into
//! triangles): 6*segments_per_side vertex columns around z, each sweeping the profile bottom
//! face -> outer wall -> top face -> hole wall.
struct NutOptions {
  int columns = 4;               //!< nuts per row (x)
  int rows = 4;                  //!< rows (y)
  double across_flats = 1.6;     //!< distance between opposite flat sides of the hexagon
  double hole_radius = 0.5;      //!< radius of the round hole
  double thickness = 0.8;        //!< height of the prism (z), below across_flats
  double size_variation = 0.1;   //!< scales drawn uniformly from [1 - v, 1 + v]; in [0, 0.5]
  double gap = 0.15;             //!< smallest horizontal distance between two nuts, > 0
  int segments_per_side = 8;     //!< segments along each hexagon side (and 1/6 of the hole)
  int wall_segments = 3;         //!< segments up each wall
  int face_segments = 2;         //!< segments across the top and bottom faces, hole to rim
  uint64_t seed = 1;             //!< seed of every random choice

  //! A small swatch for tests: 2 x 2 nuts, 4 segments per side, 2 up the walls, 1 across the
  //! faces (1,152 faces).
  static NutOptions small();
};

//! Builds the swatch: columns*rows closed genus-1 2-manifolds with outward orientation, one
//! element each (row-major), each rotated about z by an angle drawn from [0, 60) degrees and
//! scaled by a drawn factor, bottoms on z = 0, no two closer than `gap` in x-y. Same options and
//! seed, same mesh.
//! \throw InputError(invalid_option) for counts or segments < 1, hole_radius not below 0.9x the
//!        hexagon's inradius, thickness not below across_flats, non-positive sizes or gap, or
//!        size_variation outside [0, 0.5].
TriMesh make_nuts(const NutOptions& options);

}  // namespace meshquilt
