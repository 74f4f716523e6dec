#pragma once
// Designs the loom tests weave.

#include "loom/block_assignment.h"
#include "swatch/weave_pattern.h"

namespace meshquilt {

// Three regions across the columns: plain, twill 2/2, satin 5/2 (design rows run down, so row r
// reads the pattern's weft -r, as the exemplar blocks are copied).
inline LoomDesign three_regions(int size) {
  const WeavePattern patterns[3] = {twill_pattern(1, 1), twill_pattern(2, 2), satin_pattern(5, 2)};
  LoomDesign d{size, size, {}};
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) d.warp_over.push_back(patterns[3 * c / size].over(c, -r) ? 1 : 0);
  return d;
}

}  // namespace meshquilt
