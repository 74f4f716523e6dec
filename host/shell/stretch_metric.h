#pragma once
//! The L2 stretch of a shell map (Eq. 8-9 of the mesh quilting paper, after Sander et al. 2001).
//!
//! Per tetrahedron, J is the Jacobian of the map from texture space to the shell (constant on a
//! tetrahedron) and L2(T)^2 = (sigma1^2 + sigma2^2 + sigma3^2) / 3 = |J|_F^2 / 3 (Eq. 8); the
//! total is the shell-volume-weighted root mean square (Eq. 9). The map direction is Sander's
//! (texture to surface), so a value above 1 means texture elements come out enlarged.
//! Normalization: the total is multiplied by (sum |T_t| / sum |T_s|)^(1/3). In three dimensions
//! that cube root, not the square root the paper carries over from two, makes 1.0 the lower
//! bound: L2(T)^2 >= (sigma1 sigma2 sigma3)^(2/3) = (|T_s| / |T_t|)^(2/3), and Hoelder's
//! inequality gives sum |T_s|^(5/3) |T_t|^(-2/3) >= (sum |T_s|)^(5/3) (sum |T_t|)^(-2/3). A map
//! that is a similarity everywhere gives exactly 1.

#include "shell/shell_map.h"

namespace meshquilt {

struct StretchMeasure {
  double l2 = 1.0;  //!< normalized L2 stretch of the whole map
  double texture_volume = 0.0;
  double shell_volume = 0.0;
  int degenerate_tets = 0;  //!< tets of zero texture or shell volume, left out
};

StretchMeasure measure_stretch(const ShellMap& map);

}  // namespace meshquilt
