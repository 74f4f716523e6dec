#include "swatch/fruit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "swatch/layer_packing.h"
#include "swatch/swatch_random.h"

namespace meshquilt {
namespace {

// Messages name the parameters at fault as {name} (OptionError).
[[noreturn]] void invalid(const std::string& message) { throw OptionError("fruit: " + message); }
[[noreturn]] void invalid(const std::string& parameter, const std::string& problem) {
  invalid("{" + parameter + "} " + problem);
}

// Unit sphere: an icosahedron with `subdivisions` rounds of midpoint splitting, faces
// counter-clockwise seen from outside. Its triangles are near-equilateral, which suits the
// Laplacian deformation of quilting better than a latitude-longitude grid with pole fans.
TriMesh icosphere(int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriMesh m;
  m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : m.positions) p = glm::normalize(p);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int32_t, int32_t>, int32_t> midpoint;
    auto split = [&](int32_t a, int32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, inserted] = midpoint.try_emplace(key, static_cast<int32_t>(m.positions.size()));
      if (inserted) m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      return it->second;
    };
    std::vector<Tri> finer;
    finer.reserve(m.triangles.size() * 4);
    for (const Tri& f : m.triangles) {
      const int32_t ab = split(f[0], f[1]), bc = split(f[1], f[2]), ca = split(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = std::move(finer);
  }
  return m;
}

Vec3 random_direction(SwatchRandom& random) {
  const double z = random.uniform(-1.0, 1.0);
  const double phi = random.uniform(0.0, 2.0 * std::numbers::pi);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// One fruit around the origin. rho stays above 0.4 for every draw, so the surface is the radial
// graph of a positive function over the sphere: each triangle stays inside its own cone from the
// centre, which rules out self-intersections and keeps the orientation outward.
std::vector<Vec3> shape_fruit(const std::vector<Vec3>& sphere, double scale, SwatchRandom& random) {
  const Vec3 lean = random_direction(random);
  const double lopsided = random.uniform(0.0, 0.08);
  const Vec3 stretch = random_direction(random);
  const double elongation = random.uniform(-0.1, 0.1);
  const double lobes = random.uniform(0.0, 0.04);
  const double lobe_phase = random.uniform(0.0, 2.0 * std::numbers::pi);
  const double taper = random.uniform(0.02, 0.08);
  const double stem_depth = random.uniform(0.3, 0.4);
  const double calyx_depth = random.uniform(0.1, 0.2);
  const double flatten = random.uniform(0.8, 0.95);
  const double c5 = std::cos(lobe_phase), s5 = std::sin(lobe_phase);
  std::vector<Vec3> points;
  points.reserve(sphere.size());
  for (const Vec3& d : sphere) {
    // Five lobes around the axis as Re(((x + iy) e^{i phase})^5): a polynomial, hence smooth at
    // the poles where an angle-based cos(5 phi) would not be.
    const double x = d.x * c5 - d.y * s5, y = d.x * s5 + d.y * c5;
    const double x2 = x * x, y2 = y * y;
    const double fifth = x * (x2 * x2 - 10.0 * x2 * y2 + 5.0 * y2 * y2);
    const double along = glm::dot(d, stretch);
    const double rho = 1.0 + lopsided * glm::dot(d, lean) + elongation * (along * along - 1.0 / 3.0) +
                       lobes * fifth + taper * d.z - stem_depth * std::exp(-(1.0 - d.z) / 0.08) -
                       calyx_depth * std::exp(-(1.0 + d.z) / 0.05);
    points.push_back(scale * rho * Vec3(d.x, d.y, flatten * d.z));
  }
  return points;
}

}  // namespace

FruitOptions FruitOptions::small() {
  FruitOptions o;
  o.columns = 2;
  o.rows = 2;
  o.subdivisions = 2;
  return o;
}

TriMesh make_fruit(const FruitOptions& o) {
  if (o.columns < 1 || o.rows < 1) invalid("columns", "and {rows} must be >= 1");
  if (static_cast<long>(o.columns) * o.rows > 100000) invalid("more than 100000 fruit");
  if (o.subdivisions < 1 || o.subdivisions > 6) invalid("subdivisions", "must lie in 1..6");
  if (!(o.radius > 0.0) || !std::isfinite(o.radius)) invalid("radius", "must be positive");
  if (!(o.gap > 0.0) || !std::isfinite(o.gap)) invalid("gap", "must be positive");
  if (!(o.size_variation >= 0.0 && o.size_variation <= 0.5)) invalid("size_variation", "must lie in [0, 0.5]");

  const TriMesh sphere = icosphere(o.subdivisions);
  SwatchRandom random(o.seed);
  const int count = o.columns * o.rows;
  std::vector<std::vector<Vec3>> fruit(count);
  std::vector<double> footprint(count);
  for (int e = 0; e < count; ++e) {
    const double scale = o.radius * random.uniform(1.0 - o.size_variation, 1.0 + o.size_variation);
    fruit[e] = shape_fruit(sphere.positions, scale, random);
    double reach = 0.0, bottom = INFINITY;
    for (const Vec3& p : fruit[e]) {
      reach = std::max(reach, std::hypot(p.x, p.y));
      bottom = std::min(bottom, p.z);
    }
    for (Vec3& p : fruit[e]) p.z -= bottom;
    footprint[e] = reach;  // the mesh's footprint lies in the hull of its vertices' projections
  }
  const std::vector<glm::dvec2> centres = pack_jittered_grid(o.columns, o.rows, footprint, o.gap, random);
  TriMesh mesh;
  mesh.positions.reserve(sphere.positions.size() * count);
  mesh.triangles.reserve(sphere.triangles.size() * count);
  for (int e = 0; e < count; ++e) {
    const auto base = static_cast<int32_t>(mesh.positions.size());
    for (const Vec3& p : fruit[e]) mesh.positions.push_back(p + Vec3(centres[e], 0.0));
    for (const Tri& f : sphere.triangles) mesh.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    mesh.elements.resize(mesh.triangles.size(), e);
  }
  return mesh;
}

}  // namespace meshquilt
