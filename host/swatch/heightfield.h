#pragma once
//! Height-field swatches (paper 001, Sections 4.1.3 and 5): a grayscale image becomes a relief,
//! either one closed slab whose top is displaced by intensity or an open sheet.

#include "mesh/tri_mesh.h"
#include "swatch/netpbm.h"

namespace meshquilt {

//! Size and shape of a height-field swatch. One vertex per pixel centre (after downsampling),
//! the image upright seen from +z (row 0 at the largest y); white is high.
struct HeightfieldOptions {
  GrayImage image;                 //!< the heights; empty: a built-in egg-crate relief
  int builtin_resolution = 64;     //!< pixels a side of the built-in relief, >= 2
  int max_resolution = 128;        //!< larger images are box-filtered down to this many pixels
                                   //!< on their longer side, >= 2
  double size = 10.0;              //!< length of the longer side in x-y
  double height = 1.0;             //!< relief: z of white minus z of black (black at z = 0)
  double base = 0.5;               //!< slab thickness below black (bottom at z = -base)
  bool open = false;               //!< the top sheet alone (boundary edges by design)
  //! N x N tiles instead of one piece: each tile its own element over floor(W / N) x floor(H / N)
  //! pixels, one pixel spacing of grout between neighbours, so the relief quilts like any
  //! layer of discrete elements (a slab or sheet is one element as large as the swatch).
  int tiles = 1;

  //! A small swatch for tests: built-in relief at 16 x 16 pixels (closed slab: 1,020 faces).
  static HeightfieldOptions small();
};

//! The built-in relief: 0.5 + 0.5 sin(4 pi u) sin(4 pi v) over the unit square.
GrayImage builtin_height_image(int resolution);

//! Averages blocks of pixels so that the longer side has at most `max_side` pixels.
GrayImage downsample_image(const GrayImage& image, int max_side);

//! Builds the swatch: one element, or tiles x tiles of them (element ty * tiles + tx, each over
//! w x h pixels). Closed (default): a slab with top grid (heights), bottom grid (z = -base) and
//! side walls, a closed genus-0 2-manifold with outward orientation, 4 (w-1)(h-1) + 4 (w-1 + h-1)
//! faces per element. Open: the top grid alone, 2 (w-1)(h-1) faces, counter-clockwise seen
//! from +z.
//! \throw InputError(invalid_option) for an image smaller than 2 x 2 pixels, non-positive size,
//!        negative height, non-positive base (closed), a relief so tall that z would not be
//!        the thinnest axis, or tiles < 1 or leaving fewer than 3 pixels a tile.
TriMesh make_heightfield(const HeightfieldOptions& options);

}  // namespace meshquilt
