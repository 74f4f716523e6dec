#include "shell/shell.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <queue>

#include "spatial/exact_predicates.h"
#include "spatial/intersecting_pairs.h"

namespace meshquilt {
namespace {

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return glm::dot(b - a, glm::cross(c - a, d - a)) / 6.0;
}

// Lowers heights so that no two neighbours differ by more than slope x their distance.
void limit_slope(const BaseSurface& base, double slope, std::vector<double>& heights) {
  using Entry = std::pair<double, int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (size_t v = 0; v < heights.size(); ++v) queue.emplace(heights[v], static_cast<int32_t>(v));
  while (!queue.empty()) {
    const auto [h, v] = queue.top();
    queue.pop();
    if (h > heights[v]) continue;
    for (const auto& [w, length] : base.edges[v]) {
      const double limit = h + slope * length;
      if (heights[w] > limit) {
        heights[w] = limit;
        queue.emplace(limit, w);
      }
    }
  }
}

// Unit offset directions: vertex normals averaged with their neighbours' `direction_smoothing`
// times, then turned toward any face of their vertex they lean over.
std::vector<Vec3> offset_directions(const BaseSurface& base, const ShellOptions& options) {
  const size_t vertices = base.mesh.num_vertices();
  std::vector<Vec3> directions = base.vertex_normals;
  for (int pass = 0; pass < options.direction_smoothing; ++pass) {
    std::vector<Vec3> next(vertices);
    for (size_t v = 0; v < vertices; ++v) {
      Vec3 sum = directions[v];
      for (const auto& [w, length] : base.edges[v]) sum += directions[w];
      const double len = glm::length(sum);
      next[v] = len > 0.0 ? sum / len : directions[v];
    }
    directions = std::move(next);
  }
  // A prism stands only where its vertices' directions leave every face around them on the
  // outside: turn each direction toward the face it leans over most until all see it at
  // min_direction_cosine (a few steps; the plain normal where that fails).
  for (size_t v = 0; v < vertices; ++v) {
    Vec3& d = directions[v];
    for (int step = 0; step < 16; ++step) {
      double worst = 2.0;
      Vec3 worst_normal(0.0);
      for (int32_t f : base.vertex_faces[v]) {
        if (base.face_areas[f] <= 0.0) continue;
        const double c = glm::dot(d, base.face_normals[f]);
        if (c < worst) {
          worst = c;
          worst_normal = base.face_normals[f];
        }
      }
      if (worst >= options.min_direction_cosine) break;
      d = glm::normalize(d + 0.5 * worst_normal);
      if (step == 15) d = base.vertex_normals[v];
    }
  }
  return directions;
}

}  // namespace

std::array<PrismTet, 3> prism_tetrahedra(const Tri& t) {
  std::array<uint8_t, 3> k{0, 1, 2};
  std::sort(k.begin(), k.end(), [&](uint8_t a, uint8_t b) { return t[a] < t[b]; });
  // (k0 k1 k2) is a rotation of (0 1 2) or a reflection; a reflection flips every orientation.
  const bool odd = (k[1] + 3 - k[0]) % 3 != 1;
  std::array<PrismTet, 3> tets{{
      {{{k[0], 0}, {k[1], 0}, {k[2], 0}, {k[2], 1}}},
      {{{k[0], 0}, {k[1], 0}, {k[2], 1}, {k[1], 1}}},
      {{{k[0], 0}, {k[0], 1}, {k[1], 1}, {k[2], 1}}},
  }};
  if (odd)
    for (PrismTet& tet : tets) std::swap(tet[0], tet[1]);
  return tets;
}

Shell build_shell(const BaseSurface& base, double height, const ShellOptions& options) {
  const TriMesh& mesh = base.mesh;
  const size_t vertices = mesh.num_vertices(), faces = mesh.num_faces();
  Shell shell;
  shell.height = height;
  shell.heights.assign(vertices, height);
  const double floor = options.min_height_share * height;
  std::vector<uint8_t> lowered(vertices, 0);
  shell.directions = offset_directions(base, options);
  const auto place = [&] {
    shell.offset.resize(vertices);
    for (size_t v = 0; v < vertices; ++v)
      shell.offset[v] = mesh.positions[v] + shell.heights[v] * shell.directions[v];
  };
  // Faces whose prism has a flat or inverted tet.
  const auto failing_prisms = [&](bool exact_only) {
    std::vector<int32_t> failing;
    for (size_t f = 0; f < faces; ++f) {
      const Tri& t = mesh.triangles[f];
      if (base.face_areas[f] <= 0.0) continue;  // a degenerate face has a flat prism whatever the heights
      const double nominal =
          base.face_areas[f] * (shell.heights[t[0]] + shell.heights[t[1]] + shell.heights[t[2]]) / 9.0;
      for (const PrismTet& tet : prism_tetrahedra(t)) {
        const Vec3 a = shell.corner(t, tet[0], mesh.positions), b = shell.corner(t, tet[1], mesh.positions);
        const Vec3 c = shell.corner(t, tet[2], mesh.positions), d = shell.corner(t, tet[3], mesh.positions);
        const bool positive = orient3d(a, b, c, d) > 0;
        const bool thick = exact_only || signed_volume(a, b, c, d) >= options.min_volume_share * nominal;
        if (!positive || !thick) {
          failing.push_back(static_cast<int32_t>(f));
          break;
        }
      }
    }
    return failing;
  };
  // Offset faces that meet another offset face (sharing no vertex) or a base face.
  const auto crossing_offsets = [&] {
    TriMesh layers;
    layers.positions = mesh.positions;
    layers.positions.insert(layers.positions.end(), shell.offset.begin(), shell.offset.end());
    layers.triangles = mesh.triangles;
    const int32_t shift = static_cast<int32_t>(vertices);
    for (const Tri& t : mesh.triangles)
      layers.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
    std::vector<int32_t> layer(2 * faces, 0);
    std::fill(layer.begin() + static_cast<std::ptrdiff_t>(faces), layer.end(), 1);
    const FaceIntersections hits = find_intersecting_faces(layers, layer);
    std::vector<int32_t> crossing;
    for (const auto& [a, b] : hits.different_elements) crossing.push_back(b - static_cast<int32_t>(faces));
    for (const auto& [a, b] : hits.same_element)
      if (a >= static_cast<int32_t>(faces)) {
        crossing.push_back(a - static_cast<int32_t>(faces));
        crossing.push_back(b - static_cast<int32_t>(faces));
      }
    std::sort(crossing.begin(), crossing.end());
    crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
    return crossing;
  };

  place();
  for (shell.rounds = 1; shell.rounds <= options.max_rounds; ++shell.rounds) {
    std::vector<int32_t> failing = failing_prisms(false);
    if (failing.empty()) failing = crossing_offsets();
    bool changed = false;
    for (int32_t f : failing)
      for (int32_t v : mesh.triangles[f]) {
        const double lower = std::max(floor, shell.heights[v] * options.reduction);
        if (lower < shell.heights[v]) {
          shell.heights[v] = lower;
          lowered[v] = 1;
          changed = true;
        }
      }
    if (failing.empty() || !changed) break;
    limit_slope(base, options.slope, shell.heights);
    place();
  }
  for (size_t v = 0; v < vertices; ++v) {
    if (shell.heights[v] < height) lowered[v] = 1;
    shell.reduced_vertices += lowered[v];
  }
  shell.invalid_prisms = static_cast<int>(failing_prisms(true).size());
  shell.offset_intersections = static_cast<int>(crossing_offsets().size());
  return shell;
}

}  // namespace meshquilt
