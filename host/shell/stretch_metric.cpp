#include "shell/stretch_metric.h"

#include <cmath>
#include <glm/matrix.hpp>

namespace meshquilt {

StretchMeasure measure_stretch(const ShellMap& map) {
  StretchMeasure m;
  double weighted = 0.0;
  for (size_t i = 0; i < map.tet_count(); ++i) {
    const std::array<glm::dvec3, 4> q = map.texture_tet(i);
    const std::array<Vec3, 4> s = map.shell_tet(i);
    const glm::dmat3 texture(q[1] - q[0], q[2] - q[0], q[3] - q[0]);
    const glm::dmat3 shell(s[1] - s[0], s[2] - s[0], s[3] - s[0]);
    const double texture_volume = glm::determinant(texture) / 6.0;
    const double shell_volume = glm::determinant(shell) / 6.0;
    if (!(texture_volume > 0.0) || !(shell_volume > 0.0)) {
      ++m.degenerate_tets;
      continue;
    }
    const glm::dmat3 jacobian = shell * glm::inverse(texture);
    double frobenius = 0.0;
    for (int c = 0; c < 3; ++c) frobenius += glm::dot(jacobian[c], jacobian[c]);
    weighted += frobenius / 3.0 * shell_volume;
    m.texture_volume += texture_volume;
    m.shell_volume += shell_volume;
  }
  if (m.shell_volume > 0.0)
    m.l2 = std::sqrt(weighted / m.shell_volume) * std::cbrt(m.texture_volume / m.shell_volume);
  return m;
}

}  // namespace meshquilt
