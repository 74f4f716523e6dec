#pragma once
//! Woven-yarn swatches: warps along y and wefts along x passing over and under each other as a
//! weave pattern says (paper 004, Sections 3 and 5.2).

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"
#include "swatch/weave_pattern.h"

namespace meshquilt {

//! Which yarn directions a weave swatch holds.
enum class WeaveYarns {
  both,   //!< warps and wefts
  warps,  //!< the warps alone, each still crimped as if the wefts were there
  wefts,  //!< the wefts alone, likewise
};

//! Layout and tessellation of a weave swatch. Lengths are in swatch units.
//! Warp i runs along y at x = (i + 1/2) pitch, weft j along x at y = (j + 1/2) pitch; at their
//! crossing the yarn on top has its centreline at z = +amplitude, the other at -amplitude, and
//! between crossings a centreline moves by half cosine waves (C1-smooth, flat across floats).
//! pitch and yarn_radius are independent: a sparse mesh of thin wires is a small radius at a
//! large pitch (see wire()).
struct WeaveOptions {
  WeavePattern pattern = twill_pattern(1, 1);  //!< the repeat; default plain weave
  int warps = 0;                 //!< warps (along x); 0: whole repeats nearest to yarns_hint
  int wefts = 0;                 //!< wefts (along y); 0: whole repeats nearest to yarns_hint
  int yarns_hint = 10;           //!< target yarn count per direction when warps/wefts are 0
  double pitch = 1.0;            //!< distance between neighbouring parallel yarns
  double yarn_radius = 0.22;     //!< radius of a yarn's circular cross-section
  double amplitude = 0.3;        //!< height of a centreline above (below) z = 0 at a crossing
  int segments_per_pitch = 6;    //!< centreline segments per pitch of length
  int sides = 8;                 //!< vertices around a yarn's cross-section
  WeaveYarns yarns = WeaveYarns::both;  //!< which directions to build
  //! true: warps and wefts must be whole repeats of the pattern, so the swatch is periodic;
  //! false: any positive count, the swatch being a crop of the endless weave (not periodic).
  bool whole_repeats = true;

  //! A small swatch for tests: yarns_hint 4, 4 segments per pitch, 6 sides (plain: 4 x 4
  //! yarns, 1,632 faces).
  static WeaveOptions small();

  //! A sparse square mesh of crimped wires (the paper's "Plane + Wire" kind): plain weave,
  //! 9 x 9 wires of radius 0.08 at pitch 1 (6.25 diameters apart), crimp amplitude 0.12,
  //! 8 segments per pitch, 8 sides, any count accepted (21,024 faces).
  static WeaveOptions wire();

  //! wire() for tests: 5 x 5 wires, 4 segments per pitch, 5 sides (2,100 faces).
  static WeaveOptions small_wire();
};

//! Builds the swatch: one capped tube per yarn, each a closed 2-manifold with outward
//! orientation spanning the whole swatch (warps y in [0, wefts pitch], wefts x in [0, warps
//! pitch], caps perpendicular to the yarn). Element ids: warp i is i, weft j is warps + j; with
//! WeaveYarns::warps or ::wefts only that direction is built and yarn n is element n.
//! Centred on z = 0; periodic with period weave_period(options) when whole_repeats is set.
//! \throw InputError(invalid_option) for counts that are not positive (with whole_repeats: not
//!        multiples of the pattern repeat), too few segments, or sizes for which two yarns
//!        would touch (clearance of the centrelines at every kind of crossing, with the facets'
//!        bulge added; parallel yarns only when one direction is built) or a yarn would fold on
//!        itself (radius above the centreline's radius of curvature).
TriMesh make_weave(const WeaveOptions& options);

//! The (warps, wefts) the swatch will have, resolving 0 to whole repeats nearest yarns_hint.
glm::ivec2 weave_yarn_counts(const WeaveOptions& options);

//! The extent of the swatch in x and y, (warps pitch, wefts pitch); its period when the counts
//! are whole repeats.
glm::dvec2 weave_period(const WeaveOptions& options);

}  // namespace meshquilt
