#pragma once
//! A base that is a disc (one piece, one boundary, no handle) laid out whole in one chart without
//! cones: what a non-repeating design (a loom's fabric) can be draped over unbroken.

#include <string>

#include "surface/conformal_patch.h"
#include "surface/surface_types.h"

namespace meshquilt {

//! The base flattened by LSCM (Levy et al. 2002), scaled so the chart's area equals the base's,
//! centred at its area centroid and turned so the chart's longer principal axis runs along y.
struct DiscChart {
  SurfacePatch patch;           //!< every base face; locate() finds the face under a chart point
  double area_distortion = 1.0;  //!< largest over smallest face area ratio, chart over base
};

//! \throw InputError(invalid_option) naming `name` unless `base` is a disc (closed bases, several
//!        boundaries or pieces, handles), with what it is instead; SolverError from LSCM.
DiscChart disc_chart(const BaseSurface& base, const std::string& name);

}  // namespace meshquilt
