#pragma once
//! A swaying vine layer: an animated swatch (Section 4 of the mesh quilting paper animates ivy).
//! Stalks rise from a grid of roots, each a capped tube bent over in a gentle curl; every frame
//! sways them in the wind, the tip most, so that the same connectivity moves over time.

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

struct VineOptions {
  int columns = 4;       //!< stalks per row (x)
  int rows = 4;          //!< rows (y)
  double spacing = 1.0;  //!< distance between neighbouring roots
  double height = 1.5;   //!< stalk height; below spacing * min(columns, rows) so the layer is thin in z
  double radius = 0.07;  //!< tube radius
  double curl = 0.15;    //!< rest-pose lean of the tip along x, in heights
  double sway = 0.35;    //!< largest tip displacement of the animation, in heights
  int segments = 16;     //!< centreline points per stalk, >= 3
  int sides = 8;         //!< tube sides, >= 3
  uint64_t seed = 1;     //!< lean jitter per stalk

  //! A small swatch for tests: 2 x 2 stalks of height 0.8, 8 segments, 6 sides.
  static VineOptions small();
};

//! The stalks at `phase` of the sway cycle (in turns; the rest pose is make_vine(options, -1),
//! upright but for the curl): one closed capped tube per stalk, element ids row-major, roots on
//! z = 0. Every phase gives the same vertices and faces in the same order. A stalk's point at
//! height fraction t moves along x by sway * height * t^2 * sin(2 pi phase): all stalks sway
//! together, so copies packed side by side in an output never swing into each other.
//! \throw InputError(invalid_option) for counts < 1, segments < 3, sides < 3, non-positive
//!        sizes, a radius of half the spacing or more, sway beyond 0.5, or a height not below
//!        the layer's narrower x-y side (the swatch would lie on its side).
TriMesh make_vine(const VineOptions& options, double phase = -1.0);

//! `count` frames evenly over one cycle (frame k at phase k / count).
std::vector<TriMesh> make_vine_frames(const VineOptions& options, int count);

}  // namespace meshquilt
