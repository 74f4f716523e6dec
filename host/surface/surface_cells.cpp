#include "surface/surface_cells.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include "spatial/box_grid.h"

namespace meshquilt {

SurfaceCells make_surface_cells(const BaseSurface& base, double cell_size) {
  const TriMesh& mesh = base.mesh;
  SurfaceCells cells;
  std::vector<double> sizes;
  cells.face_offsets.push_back(0);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, glm::distance(mesh.positions[t[k]], mesh.positions[t[(k + 1) % 3]]));
    const int m = std::clamp(static_cast<int>(std::ceil(longest / cell_size)), 1, 4096);
    const double area = base.face_areas[f] / (static_cast<double>(m) * m);
    // Lattice sub-triangles: upright (i, j), (i+1, j), (i, j+1) and inverted ones, in b1-b2 steps of 1/m.
    for (int j = 0; j < m; ++j)
      for (int i = 0; i + j < m; ++i) {
        cells.centres.push_back({static_cast<int32_t>(f), glm::dvec2(i + 1.0 / 3.0, j + 1.0 / 3.0) / double(m)});
        cells.areas.push_back(area);
        sizes.push_back(longest / m);
        if (i + j + 1 < m) {
          cells.centres.push_back({static_cast<int32_t>(f), glm::dvec2(i + 2.0 / 3.0, j + 2.0 / 3.0) / double(m)});
          cells.areas.push_back(area);
          sizes.push_back(longest / m);
        }
      }
    cells.face_offsets.push_back(static_cast<int32_t>(cells.centres.size()));
  }

  // Neighbours through a hash of the centres, bucketed at the largest cell size.
  const size_t count = cells.centres.size();
  std::vector<Vec3> points(count);
  for (size_t c = 0; c < count; ++c) points[c] = base.position(cells.centres[c]);
  const double largest = *std::max_element(sizes.begin(), sizes.end());
  const double bucket = std::max(1.5 * largest, 1e-12);
  const auto key = [bucket](const Vec3& p) {
    return grid_cell_hash(static_cast<int64_t>(std::floor(p.x / bucket)), static_cast<int64_t>(std::floor(p.y / bucket)),
                          static_cast<int64_t>(std::floor(p.z / bucket)));
  };
  std::unordered_map<uint64_t, std::vector<int32_t>> buckets;
  for (size_t c = 0; c < count; ++c) buckets[key(points[c])].push_back(static_cast<int32_t>(c));
  cells.neighbours.resize(count);
  // Each cell's list is its own: found side by side.
  tbb::parallel_for(size_t{0}, count, [&](size_t c) {
    const Vec3& p = points[c];
    const int64_t x = static_cast<int64_t>(std::floor(p.x / bucket)), y = static_cast<int64_t>(std::floor(p.y / bucket)),
                  z = static_cast<int64_t>(std::floor(p.z / bucket));
    for (int64_t dz = -1; dz <= 1; ++dz)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dx = -1; dx <= 1; ++dx) {
          const auto it = buckets.find(grid_cell_hash(x + dx, y + dy, z + dz));
          if (it == buckets.end()) continue;
          for (int32_t d : it->second) {
            if (d == static_cast<int32_t>(c)) continue;
            const double reach = 1.5 * std::max(sizes[c], sizes[d]);
            if (glm::distance(p, points[d]) < reach) cells.neighbours[c].push_back(d);
          }
        }
    // Hash collisions may list a bucket twice.
    std::sort(cells.neighbours[c].begin(), cells.neighbours[c].end());
    cells.neighbours[c].erase(std::unique(cells.neighbours[c].begin(), cells.neighbours[c].end()),
                              cells.neighbours[c].end());
  });
  return cells;
}

}  // namespace meshquilt
