#pragma once
//! European 4-in-1 chain mail swatches: rows of tilted rings (tori), each linked through the two
//! nearest rings of the row above and the two of the row below.

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Layout and tessellation of a 4-in-1 mail swatch. Lengths are in swatch units.
//! Row r (r = 0..rows-1) holds rings at x = (c + r%2 / 2) pitch_x, y = r pitch_y, z = 0, all
//! tilted by tilt_degrees about the y axis, alternate rows the opposite way: so rings of one row
//! overlap like shingles and each ring passes through its four diagonal neighbours.
struct ChainmailOptions {
  int rows = 8;                 //!< ring rows along y; even, so the swatch is periodic in y
  int columns = 6;              //!< rings per row along x
  double ring_radius = 1.0;     //!< radius of the ring's centreline circle
  double wire_radius = 0.18;    //!< radius of the wire (the torus tube)
  double pitch_x = 1.3;         //!< distance between neighbouring rings of one row
  double pitch_y = 1.25;        //!< distance between rows
  double tilt_degrees = 31.5;   //!< tilt of each ring's plane out of x-y
  int ring_segments = 24;       //!< segments around the ring
  int wire_segments = 8;        //!< segments around the wire

  //! A small swatch for tests: 2 rows x 3 columns, 16 x 6 segments (1,152 faces).
  static ChainmailOptions small();
};

//! Builds the swatch: rows*columns rings, each a closed genus-1 2-manifold with outward
//! orientation and its own element id (row-major: id = row*columns + column). The rings are
//! centred on z = 0 and the layout repeats with period chainmail_period(options).
//! \throw InputError(invalid_option) on non-positive or odd counts, too few segments, or sizes
//!        for which two ring surfaces would touch (wire clearance checked on the centreline
//!        circles with the tessellation's deviation added) or a ring would not link exactly its
//!        four diagonal neighbours.
TriMesh make_chainmail(const ChainmailOptions& options);

//! The lattice period of the swatch in x and y: (columns pitch_x, rows pitch_y).
glm::dvec2 chainmail_period(const ChainmailOptions& options);

}  // namespace meshquilt
