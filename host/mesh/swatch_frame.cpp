#include "mesh/swatch_frame.h"

#include <glm/geometric.hpp>

#include "error.h"
#include "mesh/validation.h"

namespace meshquilt {

int thinnest_axis(const Vec3& extent) {
  if (extent.z <= extent.x && extent.z <= extent.y) return 2;
  return extent.x <= extent.y ? 0 : 1;
}

TriMesh orient_swatch(const TriMesh& swatch, const std::string& source) {
  validate_mesh(swatch, source);
  Vec3 low = swatch.positions.front();
  Vec3 high = low;
  for (const Vec3& p : swatch.positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const Vec3 extent = high - low;
  const double diagonal = glm::length(extent);
  const int height = thinnest_axis(extent);
  // A cyclic permutation (x,y,z) -> (y,z,x) or (z,x,y) has determinant +1; a swap of two axes
  // would mirror the swatch and flip every triangle.
  const int axis_x = (height + 1) % 3;
  const int axis_y = (height + 2) % 3;
  auto fail = [&](const std::string& problem) {
    throw InputError(source + ": degenerate swatch: " + problem, ExitCode::invalid_mesh);
  };
  if (!(extent[height] >= 1e-9 * diagonal) || !(diagonal > 0.0)) {
    fail("zero thickness (height " + std::to_string(extent[height]) + ", bounding-box diagonal " +
         std::to_string(diagonal) + ")");
  }
  if (!(extent[axis_x] > 0.0) || !(extent[axis_y] > 0.0)) fail("zero extent in the x-y plane");

  TriMesh out = swatch;
  for (Vec3& p : out.positions) {
    const Vec3 q = p - low;
    p = Vec3(q[axis_x], q[axis_y], q[height]);
  }
  return out;
}

}  // namespace meshquilt
