#include "swatch/layer_packing.h"

#include <algorithm>

namespace meshquilt {

std::vector<glm::dvec2> pack_jittered_grid(int columns, int rows, const std::vector<double>& radii, double gap,
                                           SwatchRandom& random) {
  const double cell = 2.0 * *std::max_element(radii.begin(), radii.end()) + gap;
  std::vector<glm::dvec2> centres;
  centres.reserve(radii.size());
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const double slack = 0.5 * cell - radii[centres.size()] - 0.5 * gap;
      const double jx = random.uniform(-slack, slack);
      const double jy = random.uniform(-slack, slack);
      centres.emplace_back((c + 0.5 + 0.5 * (r % 2)) * cell + jx, (r + 0.5) * cell + jy);
    }
  }
  return centres;
}

}  // namespace meshquilt
