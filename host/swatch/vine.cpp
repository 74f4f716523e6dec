#include "swatch/vine.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <string>

#include "core/error.h"
#include "swatch/tube_mesh.h"

namespace meshquilt {

VineOptions VineOptions::small() {
  VineOptions o;
  o.columns = 2;
  o.rows = 2;
  o.height = 0.8;
  o.segments = 8;
  o.sides = 6;
  return o;
}

namespace {

void check(const VineOptions& o) {
  const auto fail = [](const std::string& what) {
    throw InputError("vine: " + what, ErrorKind::invalid_option);
  };
  if (o.columns < 1 || o.rows < 1) fail("columns and rows must be at least 1");
  if (o.segments < 3 || o.sides < 3) fail("segments and sides must be at least 3");
  if (!(o.spacing > 0.0 && o.height > 0.0 && o.radius > 0.0))
    fail("spacing, height and radius must be positive");
  if (!(o.radius < 0.5 * o.spacing)) fail("the radius must be below half the spacing");
  if (!(o.sway >= 0.0 && o.sway <= 0.5)) fail("sway must lie in [0, 0.5]");
  if (!(std::abs(o.curl) <= 0.5)) fail("curl must lie in [-0.5, 0.5]");
  // Thinner in z than across, or the swatch would be turned on its side.
  if (!(o.height < o.spacing * (std::min(o.columns, o.rows) - 1) + 2.0 * o.radius))
    fail(
        "the height must be below the layer's narrower side (spacing x (min(columns, rows) - 1) + 2 radius)");
}

}  // namespace

TriMesh make_vine(const VineOptions& o, double phase) {
  check(o);
  std::mt19937_64 random(o.seed);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);  // the lean of each stalk
  const double tau = 2.0 * 3.14159265358979323846;
  TriMesh mesh;
  int32_t element = 0;
  for (int row = 0; row < o.rows; ++row)
    for (int column = 0; column < o.columns; ++column) {
      const double lean = o.curl * (1.0 + 0.3 * jitter(random));
      // One phase for every stalk: copies of the swatch packed side by side in the output sway
      // together, so neighbours from different copies never swing into each other.
      const double wave = 0.0;
      const Vec3 root(o.spacing * (column + 0.5), o.spacing * (row + 0.5), 0.0);
      const double swing = phase < 0.0 ? 0.0 : o.sway * std::sin(tau * (phase + wave));
      std::vector<Vec3> centre, tangent, normal;
      for (int k = 0; k < o.segments; ++k) {
        // Roots sit a radius above z = 0 so the cap does not pass below it.
        const double t = static_cast<double>(k) / (o.segments - 1);
        const double bend = (lean + swing) * o.height;
        centre.push_back(root + Vec3(bend * t * t, 0.0, o.radius + (o.height - 2.0 * o.radius) * t));
        const Vec3 d = glm::normalize(Vec3(2.0 * bend * t, 0.0, o.height - 2.0 * o.radius));
        tangent.push_back(d);
        normal.push_back(glm::normalize(glm::cross(Vec3(0.0, 1.0, 0.0), d)));
      }
      append_tube(mesh, centre, normal, o.radius, o.sides, TubeEnds::capped, element++, tangent);
    }
  return mesh;
}

std::vector<TriMesh> make_vine_frames(const VineOptions& options, int count) {
  std::vector<TriMesh> frames;
  for (int k = 0; k < count; ++k) frames.push_back(make_vine(options, static_cast<double>(k) / count));
  return frames;
}

}  // namespace meshquilt
