#include "spatial/near_face_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "mesh/measures.h"
#include "spatial/face_bvh.h"

namespace meshquilt {

int64_t NearFaceGrid::voxel_of(const Vec3& q) const {
  const Vec3 rel = (q - origin) / voxel;
  if (!(rel.x >= 0.0 && rel.y >= 0.0 && rel.z >= 0.0)) return -1;  // also NaN
  const auto i = static_cast<int64_t>(rel.x), j = static_cast<int64_t>(rel.y), k = static_cast<int64_t>(rel.z);
  if (i >= size.x || j >= size.y || k >= size.z) return -1;
  return (k * size.y + j) * size.x + i;
}

NearFaceGrid build_near_face_grid(const TriMesh& mesh, double voxel, double margin, double list_margin, double far,
                                  int max_list, int64_t max_voxels, const std::vector<uint32_t>& face_groups) {
  const auto label = [&](uint32_t f) { return face_groups.empty() ? 0u : face_groups[f]; };
  const uint32_t labels = face_groups.empty() ? 1u : *std::max_element(face_groups.begin(), face_groups.end()) + 1;
  NearFaceGrid grid;
  grid.box_low = Vec3(std::numeric_limits<double>::infinity());
  grid.box_high = -grid.box_low;
  for (const Tri& t : mesh.triangles)
    for (int32_t v : t) {
      grid.box_low = glm::min(grid.box_low, mesh.positions[v]);
      grid.box_high = glm::max(grid.box_high, mesh.positions[v]);
    }
  const Vec3 extent = grid.box_high - grid.box_low + 2.0 * margin;
  auto voxels_along = [](double length, double edge) { return static_cast<int64_t>(std::ceil(length / edge)) + 1; };
  while (voxels_along(extent.x, voxel) * voxels_along(extent.y, voxel) * voxels_along(extent.z, voxel) > max_voxels)
    voxel *= 1.25;
  grid.voxel = voxel;
  grid.origin = grid.box_low - margin;
  grid.size = glm::ivec3(voxels_along(extent.x, voxel), voxels_along(extent.y, voxel), voxels_along(extent.z, voxel));
  const glm::ivec3 n = grid.size;
  const int64_t count = static_cast<int64_t>(n.x) * n.y * n.z;
  // Far enough past a voxel's wall that a point rounded into the next voxel still counts.
  const double pad = 1e-6 * voxel + 1e-9 * glm::length(grid.box_high - grid.box_low);

  // Buckets: every face in each voxel its bounding box touches.
  auto voxel_range = [&](const Tri& t, glm::ivec3& lo, glm::ivec3& hi) {
    Vec3 low = mesh.positions[t[0]], high = low;
    for (int32_t v : {t[1], t[2]}) {
      low = glm::min(low, mesh.positions[v]);
      high = glm::max(high, mesh.positions[v]);
    }
    lo = glm::clamp(glm::ivec3(glm::floor((low - grid.origin) / voxel)), glm::ivec3(0), n - 1);
    hi = glm::clamp(glm::ivec3(glm::floor((high - grid.origin) / voxel)), glm::ivec3(0), n - 1);
  };
  auto index = [&](int i, int j, int k) { return (static_cast<int64_t>(k) * n.y + j) * n.x + i; };
  std::vector<uint32_t> bucket_start(count + 1, 0);
  glm::ivec3 lo, hi;
  for (const Tri& t : mesh.triangles) {
    voxel_range(t, lo, hi);
    for (int k = lo.z; k <= hi.z; ++k)
      for (int j = lo.y; j <= hi.y; ++j)
        for (int i = lo.x; i <= hi.x; ++i) ++bucket_start[index(i, j, k) + 1];
  }
  for (int64_t v = 0; v < count; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<uint32_t> bucket(bucket_start[count]);
  {
    std::vector<uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      voxel_range(mesh.triangles[f], lo, hi);
      for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
          for (int i = lo.x; i <= hi.x; ++i) bucket[fill[index(i, j, k)]++] = static_cast<uint32_t>(f);
    }
  }

  const std::vector<FaceSphere> spheres = face_spheres(mesh);
  // Every point within pad of a voxel lies within `radius` of its centre.
  const double radius = 0.5 * std::sqrt(3.0) * voxel * (1.0 + 1e-9) + std::sqrt(3.0) * pad;
  struct Scratch {
    std::vector<uint32_t> stamp;
    uint32_t current = 0;
    std::vector<std::pair<double, uint32_t>> found;
    std::vector<uint32_t> label_count;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  // Voxels in fixed chunks, each listing into its own flat arrays, joined in order afterwards.
  struct Part {
    std::vector<uint32_t> faces, counts;
    std::vector<float> near;
    std::vector<uint32_t> group_counts, group_sizes, group_labels;  // groups per voxel; entries and label per group
    std::vector<int64_t> far_voxels;  // listing none
  };
  constexpr int64_t kChunk = 1024;
  std::vector<Part> parts(static_cast<size_t>((count + kChunk - 1) / kChunk));
  grid.reach.assign(count, 0.0);
  tbb::parallel_for(size_t{0}, parts.size(), [&](size_t part) {
    Scratch& s = scratch.local();
    if (s.stamp.empty()) s.stamp.assign(mesh.num_faces(), 0);
    Part& out = parts[part];
    for (int64_t v = static_cast<int64_t>(part) * kChunk; v < std::min(count, static_cast<int64_t>(part + 1) * kChunk); ++v) {
      const int i = static_cast<int>(v % n.x), j = static_cast<int>((v / n.x) % n.y), k = static_cast<int>(v / (int64_t{n.x} * n.y));
      const Vec3 centre = grid.origin + (Vec3(i, j, k) + 0.5) * voxel;
      if (++s.current == 0) {  // the stamps wrapped around
        std::fill(s.stamp.begin(), s.stamp.end(), 0);
        s.current = 1;
      }
      s.found.clear();
      double nearest = std::numeric_limits<double>::infinity();
      // After shell `shell` every face with a point within (shell + 0.5) voxels of the centre
      // (in the max norm, hence also in the Euclidean one) has been found, with its distance.
      double cutoff = std::numeric_limits<double>::infinity();
      auto scan_shell = [&](int shell) {
        const glm::ivec3 a = glm::max(glm::ivec3(i, j, k) - shell, glm::ivec3(0));
        const glm::ivec3 b = glm::min(glm::ivec3(i, j, k) + shell, n - 1);
        // Only the cells of the shell itself: whole rows on its z and y faces, the two ends of
        // every other row.
        for (int z = a.z; z <= b.z; ++z)
          for (int y = a.y; y <= b.y; ++y) {
            const bool whole_row = std::abs(z - k) == shell || std::abs(y - j) == shell;
            const int step = whole_row || shell == 0 ? 1 : 2 * shell;
            for (int x = whole_row ? a.x : i - shell; x <= (whole_row ? b.x : i + shell); x += step) {
              if (x < a.x || x > b.x) continue;
              const int64_t cell = index(x, y, z);
              for (uint32_t m = bucket_start[cell]; m < bucket_start[cell + 1]; ++m) {
                const uint32_t f = bucket[m];
                if (s.stamp[f] == s.current) continue;
                s.stamp[f] = s.current;
                // A face whose bounding sphere lies past `cutoff` is not listed; its distance
                // only bounds the reach, and the sphere's gap bounds that as well.
                const double gap = glm::length(centre - spheres[f].centre) - spheres[f].radius;
                if (gap > cutoff) {
                  s.found.emplace_back(gap, f);
                  continue;
                }
                const Tri& t = mesh.triangles[f];
                const double d = closest_point_on_triangle(centre, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]).distance;
                s.found.emplace_back(d, f);
                nearest = std::min(nearest, d);
              }
            }
          }
      };
      // Past every voxel, or once every face is found, further shells find nothing.
      const int last_shell = std::max({n.x, n.y, n.z});
      const auto all_found = [&] { return s.found.size() == mesh.num_faces(); };
      int shell = 0;
      auto covered = [&] { return (shell + 0.5) * voxel; };
      scan_shell(0);
      while (covered() < std::min(nearest, far) && shell < last_shell && !all_found()) scan_shell(++shell);
      if (all_found()) shell = last_shell;
      double lowest = std::numeric_limits<double>::infinity();
      for (const auto& found : s.found) lowest = std::min(lowest, found.first);
      if (lowest > far) {
        grid.reach[v] = std::clamp(std::min(lowest, shell >= last_shell ? lowest : covered()) - radius, 0.0,
                                   std::numeric_limits<double>::max());
        out.counts.push_back(0);
        out.group_counts.push_back(0);
        out.far_voxels.push_back(v);
        continue;
      }
      const double list_radius = nearest + 2.0 * radius + list_margin;
      cutoff = list_radius;
      while (covered() < list_radius && shell < last_shell && !all_found()) scan_shell(++shell);
      if (all_found()) shell = last_shell;
      // Only the faces within the list's radius need an order (most found faces lie beyond it).
      const auto within = std::partition(s.found.begin(), s.found.end(),
                                         [&](const auto& found) { return found.first <= list_radius; });
      std::sort(s.found.begin(), within);
      const size_t listed = std::min(static_cast<size_t>(within - s.found.begin()), static_cast<size_t>(max_list));
      double unlisted = std::numeric_limits<double>::infinity();
      for (auto it = s.found.begin() + static_cast<std::ptrdiff_t>(listed); it != s.found.end(); ++it)
        unlisted = std::min(unlisted, it->first);
      // Finite even when every face is listed, so that lambda * reach is never 0 x infinity.
      grid.reach[v] = std::clamp(std::min(unlisted, shell >= last_shell ? unlisted : covered()) - radius, 0.0,
                                 std::numeric_limits<double>::max());
      out.counts.push_back(static_cast<uint32_t>(listed));
      // Groups by label (a counting sort, which keeps each group nearest first).
      s.label_count.assign(labels, 0);
      for (size_t m = 0; m < listed; ++m) ++s.label_count[label(s.found[m].second)];
      uint32_t groups = 0, offset = 0;
      for (uint32_t l = 0; l < labels; ++l) {
        if (s.label_count[l] == 0) continue;
        ++groups;
        out.group_labels.push_back(l);
        out.group_sizes.push_back(s.label_count[l]);
        const uint32_t size = s.label_count[l];
        s.label_count[l] = offset;  // now where the group starts
        offset += size;
      }
      out.group_counts.push_back(groups);
      const size_t base = out.faces.size();
      out.faces.resize(base + listed);
      out.near.resize(base + listed);
      for (size_t m = 0; m < listed; ++m) {
        const double near = std::max(s.found[m].first - radius, 0.0);
        float rounded = static_cast<float>(near);
        if (static_cast<double>(rounded) > near) rounded = std::nextafter(rounded, 0.0f);
        const size_t at = base + s.label_count[label(s.found[m].second)]++;
        out.faces[at] = s.found[m].second;
        out.near[at] = rounded;
      }
    }
  });
  // A far voxel's reach is the nearest face's distance from its centre, less the radius: the
  // shells above stop at `far`, which between widely spaced elements (the fruit) bounded points
  // many times nearer than they are, and left the kernel's bounds too low to prune candidates.
  std::vector<int64_t> far_voxels;
  for (const Part& part : parts) far_voxels.insert(far_voxels.end(), part.far_voxels.begin(), part.far_voxels.end());
  if (!far_voxels.empty()) {
    const FaceBvh bvh(mesh);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, far_voxels.size(), 256), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t m = range.begin(); m != range.end(); ++m) {
        const int64_t w = far_voxels[m];
        const int i = static_cast<int>(w % n.x), j = static_cast<int>((w / n.x) % n.y), k = static_cast<int>(w / (int64_t{n.x} * n.y));
        const Vec3 centre = grid.origin + (Vec3(i, j, k) + 0.5) * voxel;
        grid.reach[w] = std::max(grid.reach[w], bvh.closest_point(centre).distance - radius);
      }
    });
  }
  grid.start.assign(count + 1, 0);
  grid.group_start.assign(count + 1, 0);
  grid.group_first.assign(1, 0);
  int64_t v = 0;
  for (Part& part : parts) {
    for (size_t m = 0; m < part.counts.size(); ++m) {
      grid.start[v + 1] = grid.start[v] + part.counts[m];
      grid.group_start[v + 1] = grid.group_start[v] + part.group_counts[m];
      ++v;
    }
    for (uint32_t size : part.group_sizes) grid.group_first.push_back(grid.group_first.back() + size);
    grid.group_label.insert(grid.group_label.end(), part.group_labels.begin(), part.group_labels.end());
    grid.faces.insert(grid.faces.end(), part.faces.begin(), part.faces.end());
    grid.near.insert(grid.near.end(), part.near.begin(), part.near.end());
    part = Part{};  // released as it is joined
  }
  return grid;
}

}  // namespace meshquilt
