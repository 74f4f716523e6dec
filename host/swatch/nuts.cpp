#include "swatch/nuts.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/constants.h"
#include "core/error.h"
#include "swatch/layer_packing.h"
#include "swatch/swatch_random.h"

namespace meshquilt {
namespace {


// Messages name the parameters at fault as {name} (OptionError).
[[noreturn]] void invalid(const std::string& message) { throw OptionError("nuts: " + message); }
[[noreturn]] void invalid(const std::string& parameter, const std::string& problem) {
  invalid("{" + parameter + "} " + problem);
}

struct ProfilePoint {
  double lambda;  // 0 on the hole, 1 on the hexagon
  double z;
};

// The closed profile swept around the axis, counter-clockwise in the (radial, z) half-plane:
// bottom face outwards, outer wall up, top face inwards, hole wall down. Sweeping it around z
// gives a closed quad grid with the topology of a torus.
std::vector<ProfilePoint> nut_profile(const NutOptions& o, double height) {
  std::vector<ProfilePoint> profile;
  const int across = o.face_segments, up = o.wall_segments;
  for (int l = 0; l < across; ++l) profile.push_back({static_cast<double>(l) / across, 0.0});
  for (int l = 0; l < up; ++l) profile.push_back({1.0, height * l / up});
  for (int l = 0; l < across; ++l) profile.push_back({1.0 - static_cast<double>(l) / across, height});
  for (int l = 0; l < up; ++l) profile.push_back({0.0, height - height * l / up});
  return profile;
}

}  // namespace

NutOptions NutOptions::small() {
  NutOptions o;
  o.columns = 2;
  o.rows = 2;
  o.segments_per_side = 4;
  o.wall_segments = 2;
  o.face_segments = 1;
  return o;
}

TriMesh make_nuts(const NutOptions& o) {
  if (o.columns < 1 || o.rows < 1) invalid("columns", "and {rows} must be >= 1");
  if (static_cast<long>(o.columns) * o.rows > 100000) invalid("more than 100000 nuts");
  if (o.segments_per_side < 1 || o.wall_segments < 1 || o.face_segments < 1) invalid("segment counts must be >= 1");
  if (o.segments_per_side > 256 || o.wall_segments > 256 || o.face_segments > 256) invalid("segment counts must be <= 256");
  if (!(o.across_flats > 0.0) || !std::isfinite(o.across_flats)) invalid("across_flats", "must be positive");
  const double inradius = 0.5 * o.across_flats;
  if (!(o.hole_radius > 0.0) || !(o.hole_radius < 0.9 * inradius)) {
    invalid("hole_radius", "must be positive and below 0.9x half of {across_flats} (" + std::to_string(0.9 * inradius) + ")");
  }
  if (!(o.thickness > 0.0) || !(o.thickness < o.across_flats)) invalid("thickness", "must be positive and below {across_flats}");
  if (!(o.gap > 0.0) || !std::isfinite(o.gap)) invalid("gap", "must be positive");
  if (!(o.size_variation >= 0.0 && o.size_variation <= 0.5)) invalid("size_variation", "must lie in [0, 0.5]");

  SwatchRandom random(o.seed);
  const int count = o.columns * o.rows;
  std::vector<double> scale(count), turn(count), footprint(count);
  const double circumradius = inradius / std::cos(kPi / 6.0);
  for (int e = 0; e < count; ++e) {
    scale[e] = random.uniform(1.0 - o.size_variation, 1.0 + o.size_variation);
    turn[e] = random.uniform(0.0, kPi / 3.0);
    footprint[e] = circumradius * scale[e];
  }
  const std::vector<glm::dvec2> centres = pack_jittered_grid(o.columns, o.rows, footprint, o.gap, random);

  const int around = 6 * o.segments_per_side;
  TriMesh mesh;
  for (int e = 0; e < count; ++e) {
    const std::vector<ProfilePoint> profile = nut_profile(o, o.thickness * scale[e]);
    const int ring = static_cast<int>(profile.size());
    const auto base = static_cast<int32_t>(mesh.positions.size());
    for (int q = 0; q < around; ++q) {
      const int side = q / o.segments_per_side;
      const double t = static_cast<double>(q % o.segments_per_side) / o.segments_per_side;
      const double a0 = turn[e] + side * kPi / 3.0, a1 = a0 + kPi / 3.0;
      const glm::dvec2 rim = footprint[e] * ((1.0 - t) * glm::dvec2(std::cos(a0), std::sin(a0)) +
                                             t * glm::dvec2(std::cos(a1), std::sin(a1)));
      // The hole vertex sits on the rim vertex's ray, so every face quad lies between two rays
      // and is convex.
      const glm::dvec2 hole = o.hole_radius * scale[e] * rim / std::sqrt(rim.x * rim.x + rim.y * rim.y);
      for (const ProfilePoint& p : profile) {
        const glm::dvec2 xy = hole + p.lambda * (rim - hole) + centres[e];
        mesh.positions.emplace_back(xy.x, xy.y, p.z);
      }
    }
    auto vertex = [&](int q, int p) { return base + (q % around) * ring + (p % ring); };
    // Around z, then along the counter-clockwise profile: the corner order below faces outward.
    for (int q = 0; q < around; ++q) {
      for (int p = 0; p < ring; ++p) {
        const int32_t a = vertex(q, p), b = vertex(q + 1, p), c = vertex(q + 1, p + 1), d = vertex(q, p + 1);
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      }
    }
    mesh.elements.resize(mesh.triangles.size(), e);
  }
  return mesh;
}

}  // namespace meshquilt
