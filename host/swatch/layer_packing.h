#pragma once
//! Placing round footprints in one layer without contact: the packing of fruit and nut swatches.

#include <vector>

#include <glm/vec2.hpp>

#include "swatch/swatch_random.h"

namespace meshquilt {

//! Centres for columns x rows footprints (discs of the given radii, row-major) on a jittered
//! grid: square cells of side 2 max(radius) + gap, odd rows shifted by half a cell, each centre
//! moved at random within its cell as far as keeps its disc `gap`/2 inside the cell. So no two
//! discs come closer than `gap`.
//! radii  #columns*rows, positive
std::vector<glm::dvec2> pack_jittered_grid(int columns, int rows, const std::vector<double>& radii, double gap,
                                           SwatchRandom& random);

}  // namespace meshquilt
