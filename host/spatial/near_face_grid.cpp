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
#include "core/populate_pages.h"
#include "spatial/face_bvh.h"

namespace meshquilt {

int64_t NearFaceGrid::voxel_of(const Vec3& q) const {
  const Vec3 rel = (q - origin) / voxel;
  if (!(rel.x >= 0.0 && rel.y >= 0.0 && rel.z >= 0.0)) return -1;  // also NaN
  const auto i = static_cast<int64_t>(rel.x), j = static_cast<int64_t>(rel.y), k = static_cast<int64_t>(rel.z);
  if (i >= size.x || j >= size.y || k >= size.z) return -1;
  return (k * size.y + j) * size.x + i;
}

namespace {

// Builds a NearFaceGrid in steps: size the grid, bucket the faces, list the voxels block by block
// into one part per row, reach the far voxels through the BVH, join the parts.
class NearFaceGridBuilder {
 public:
  NearFaceGridBuilder(const TriMesh& mesh, double list_margin, double far, int max_list,
                      const std::vector<uint32_t>& face_groups)
      : mesh_(mesh), list_margin_(list_margin), far_(far), max_list_(max_list), face_groups_(face_groups),
        labels_(face_groups.empty() ? 1u : *std::max_element(face_groups.begin(), face_groups.end()) + 1),
        spheres_(face_spheres(mesh)), planes_(face_planes(mesh)), bvh_(mesh) {}

  NearFaceGrid build(double voxel, double margin, int64_t max_voxels) {
    size_grid(voxel, margin, max_voxels);
    bucket_faces();
    list_voxels();
    reach_far_voxels();
    join_parts();
    return std::move(grid_);
  }

 private:
  struct Candidate {
    double gap;  // of the face's bounding sphere from the block's centre
    uint32_t face;
  };
  struct Scratch {
    std::vector<uint32_t> stamp;
    uint32_t current = 0;
    std::vector<Candidate> candidates;
    std::vector<double> gaps, distances;  // per candidate, from one voxel's centre (-1: not computed)
    std::vector<std::pair<double, uint32_t>> found;
    std::vector<uint32_t> label_count;
  };
  // One part per row of voxels (fixed j, k), listing into its own flat arrays, joined in order.
  struct Part {
    std::vector<uint32_t> faces, counts;
    std::vector<float> near;
    std::vector<uint32_t> group_counts, group_sizes, group_labels;  // groups per voxel; entries and label per group
    std::vector<int64_t> far_voxels;  // listing none
  };

  uint32_t label(uint32_t f) const { return face_groups_.empty() ? 0u : face_groups_[f]; }
  int64_t index(int i, int j, int k) const { return (static_cast<int64_t>(k) * n_.y + j) * n_.x + i; }
  Vec3 centre_of(int i, int j, int k) const { return grid_.origin + (Vec3(i, j, k) + 0.5) * voxel_; }

  void size_grid(double voxel, double margin, int64_t max_voxels) {
    grid_.box_low = Vec3(std::numeric_limits<double>::infinity());
    grid_.box_high = -grid_.box_low;
    for (const Tri& t : mesh_.triangles)
      for (int32_t v : t) {
        grid_.box_low = glm::min(grid_.box_low, mesh_.positions[v]);
        grid_.box_high = glm::max(grid_.box_high, mesh_.positions[v]);
      }
    const Vec3 extent = grid_.box_high - grid_.box_low + 2.0 * margin;
    auto voxels_along = [](double length, double edge) { return static_cast<int64_t>(std::ceil(length / edge)) + 1; };
    while (voxels_along(extent.x, voxel) * voxels_along(extent.y, voxel) * voxels_along(extent.z, voxel) > max_voxels)
      voxel *= 1.25;
    grid_.voxel = voxel_ = voxel;
    grid_.origin = grid_.box_low - margin;
    grid_.size = n_ =
        glm::ivec3(voxels_along(extent.x, voxel), voxels_along(extent.y, voxel), voxels_along(extent.z, voxel));
    count_ = static_cast<int64_t>(n_.x) * n_.y * n_.z;
    // Far enough past a voxel's wall that a point rounded into the next voxel still counts.
    pad_ = 1e-6 * voxel + 1e-9 * glm::length(grid_.box_high - grid_.box_low);
    // Every point within pad of a voxel lies within `radius` of its centre.
    radius_ = 0.5 * std::sqrt(3.0) * voxel * (1.0 + 1e-9) + std::sqrt(3.0) * pad_;
    slack_ = 1e-9 * voxel;  // keeps the early stops below conservative under rounding
  }

  // Buckets: every face in each voxel its bounding box touches. Per face its box too: with its
  // plane, the bounds of listed entries.
  void bucket_faces() {
    auto voxel_range = [&](const Tri& t, glm::ivec3& lo, glm::ivec3& hi) {
      Vec3 low = mesh_.positions[t[0]], high = low;
      for (int32_t v : {t[1], t[2]}) {
        low = glm::min(low, mesh_.positions[v]);
        high = glm::max(high, mesh_.positions[v]);
      }
      lo = glm::clamp(glm::ivec3(glm::floor((low - grid_.origin) / voxel_)), glm::ivec3(0), n_ - 1);
      hi = glm::clamp(glm::ivec3(glm::floor((high - grid_.origin) / voxel_)), glm::ivec3(0), n_ - 1);
    };
    bucket_start_.assign(count_ + 1, 0);
    glm::ivec3 lo, hi;
    for (const Tri& t : mesh_.triangles) {
      voxel_range(t, lo, hi);
      for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
          for (int i = lo.x; i <= hi.x; ++i) ++bucket_start_[index(i, j, k) + 1];
    }
    for (int64_t v = 0; v < count_; ++v) bucket_start_[v + 1] += bucket_start_[v];
    bucket_.assign(bucket_start_[count_], 0);
    std::vector<uint32_t> fill(bucket_start_.begin(), bucket_start_.end() - 1);
    for (size_t f = 0; f < mesh_.num_faces(); ++f) {
      voxel_range(mesh_.triangles[f], lo, hi);
      for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
          for (int i = lo.x; i <= hi.x; ++i) bucket_[fill[index(i, j, k)]++] = static_cast<uint32_t>(f);
    }
    boxes_.resize(mesh_.num_faces());
    for (size_t f = 0; f < mesh_.num_faces(); ++f) {
      const Tri& t = mesh_.triangles[f];
      const Vec3 &a = mesh_.positions[t[0]], &b = mesh_.positions[t[1]], &c = mesh_.positions[t[2]];
      boxes_[f] = {glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c)};
    }
  }

  // Voxels are listed in blocks of up to 2 x 2 x 2: a block gathers once the faces that can
  // matter to any of its voxels (those within R of its centre c, R = the nearest face's distance
  // from c + 2 h + 2 radius + list_margin, h the farthest voxel centre from c), sorted by their
  // bounding spheres' gap from c; each voxel then reads that array only as far as its own list
  // reaches. A voxel's list is the same as a search around the voxel alone would give: its
  // nearest face lies within R of c, and so does every face within its list's radius (at most
  // its nearest distance + 2 radius + list_margin, and its nearest distance is at most c's + h).
  void list_voxels() {
    parts_.assign(static_cast<size_t>(n_.y) * n_.z, Part{});
    grid_.reach.assign(count_, 0.0);
    grid_.nearest_face.assign(count_, -1);
    tbb::enumerable_thread_specific<Scratch> scratch;
    const int brick_rows_y = (n_.y + 1) / 2, brick_rows_z = (n_.z + 1) / 2;
    tbb::parallel_for(0, brick_rows_y * brick_rows_z, [&](int brick_row) {
      Scratch& s = scratch.local();
      if (s.stamp.empty()) s.stamp.assign(mesh_.num_faces(), 0);
      const int j0 = 2 * (brick_row % brick_rows_y), k0 = 2 * (brick_row / brick_rows_y);
      const int j1 = std::min(j0 + 1, n_.y - 1), k1 = std::min(k0 + 1, n_.z - 1);
      for (int i0 = 0; i0 < n_.x; i0 += 2) {
        const int i1 = std::min(i0 + 1, n_.x - 1);
        const Vec3 c = 0.5 * (centre_of(i0, j0, k0) + centre_of(i1, j1, k1));
        const double h = 0.5 * glm::length(centre_of(i1, j1, k1) - centre_of(i0, j0, k0)) * (1.0 + 1e-12);
        const double block_nearest = bvh_.closest_point(c).distance;
        const double reach_limit = block_nearest + 2.0 * h + 2.0 * radius_ + list_margin_;  // R
        // Voxels whose every face lies past `far` list none (their reach comes from the BVH).
        const bool block_far = block_nearest - h > far_;
        s.candidates.clear();
        if (!block_far) gather(s, c, reach_limit);
        for (int k = k0; k <= k1; ++k)
          for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i)
              list_voxel(s, parts_[static_cast<size_t>(k) * n_.y + j], i, j, k, c, reach_limit, block_far);
      }
    });
  }

  // The faces that can matter to a block's voxels, nearest sphere first (see list_voxels).
  void gather(Scratch& s, const Vec3& c, double reach_limit) const {
    if (++s.current == 0) {  // the stamps wrapped around
      std::fill(s.stamp.begin(), s.stamp.end(), 0);
      s.current = 1;
    }
    // Every face with a point within R of c is bucketed in a cell of c's box of half side R.
    const glm::ivec3 lo =
        glm::clamp(glm::ivec3(glm::floor((c - reach_limit - grid_.origin) / voxel_)), glm::ivec3(0), n_ - 1);
    const glm::ivec3 hi =
        glm::clamp(glm::ivec3(glm::floor((c + reach_limit - grid_.origin) / voxel_)), glm::ivec3(0), n_ - 1);
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int64_t cell = index(lo.x, y, z), end = index(hi.x, y, z); cell <= end; ++cell)
          for (uint32_t m = bucket_start_[cell]; m < bucket_start_[cell + 1]; ++m) {
            const uint32_t f = bucket_[m];
            if (s.stamp[f] == s.current) continue;
            s.stamp[f] = s.current;
            const double gap = glm::length(c - spheres_[f].centre) - spheres_[f].radius;
            if (gap <= reach_limit) s.candidates.push_back({gap, f});
          }
    std::sort(s.candidates.begin(), s.candidates.end(),
              [](const Candidate& x, const Candidate& y) { return x.gap != y.gap ? x.gap < y.gap : x.face < y.face; });
    s.gaps.resize(s.candidates.size());
    s.distances.resize(s.candidates.size());
  }

  static bool nearer(const std::pair<double, uint32_t>& x, const std::pair<double, uint32_t>& y) {
    return x.first < y.first || (x.first == y.first && x.second < y.second);
  }

  // Lists voxel (i, j, k) of the block around c from the block's candidates.
  void list_voxel(Scratch& s, Part& out, int i, int j, int k, const Vec3& c, double reach_limit, bool block_far) {
    const int64_t v = index(i, j, k);
    const Vec3 centre = centre_of(i, j, k);
    const double offset = glm::length(centre - c);  // a face's gap from here >= its gap from c - offset
    const auto gap_here = [&](uint32_t f) { return glm::length(centre - spheres_[f].centre) - spheres_[f].radius; };
    const auto distance = [&](uint32_t f) {
      const Tri& t = mesh_.triangles[f];
      return closest_point_on_triangle(centre, mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]])
          .distance;
    };
    // The first pass finds the nearest face; the second lists. The first pass's gaps and
    // distances (of a prefix of the candidates) are kept for the second.
    double nearest = std::numeric_limits<double>::infinity();
    size_t seen = 0;
    for (; seen < s.candidates.size(); ++seen) {
      const Candidate& cand = s.candidates[seen];
      if (cand.gap - offset >= nearest + slack_) break;
      const double gap = gap_here(cand.face);
      s.gaps[seen] = gap;
      s.distances[seen] = -1.0;
      if (gap < nearest) {
        s.distances[seen] = distance(cand.face);
        nearest = std::min(nearest, s.distances[seen]);
      }
    }
    if (block_far || nearest > far_) {
      out.counts.push_back(0);
      out.group_counts.push_back(0);
      out.far_voxels.push_back(v);
      return;
    }
    const double list_radius = nearest + 2.0 * radius_ + list_margin_;
    // Faces not gathered are farther than R - offset from the centre.
    double unlisted = reach_limit - offset;
    // What a voxel needs is its nearest max_list + 1 faces within list_radius: the listed ones
    // and the nearest of the rest. Whenever twice that many are found, the farther half is
    // dropped (none is nearer than the kept ones, so `unlisted` loses nothing), and the farthest
    // kept face's distance bounds what can still enter: a face whose gap (a lower bound of its
    // distance) passes it is skipped.
    const size_t keep = static_cast<size_t>(max_list_) + 1;
    double bound = list_radius;
    s.found.clear();
    for (size_t m = 0; m < s.candidates.size(); ++m) {
      const Candidate& cand = s.candidates[m];
      if (cand.gap - offset > bound + slack_) {
        unlisted = std::min(unlisted, cand.gap - offset);  // the nearest of the rest
        break;
      }
      const double gap = m < seen ? s.gaps[m] : gap_here(cand.face);
      if (gap > bound) {
        unlisted = std::min(unlisted, gap);
        continue;
      }
      const double d = m < seen && s.distances[m] >= 0.0 ? s.distances[m] : distance(cand.face);
      if (d > bound) {
        unlisted = std::min(unlisted, d);
        continue;
      }
      s.found.emplace_back(d, cand.face);
      if (s.found.size() == 2 * keep) {
        const auto farthest_kept = s.found.begin() + static_cast<std::ptrdiff_t>(keep - 1);
        std::nth_element(s.found.begin(), farthest_kept, s.found.end(), nearer);
        s.found.resize(keep);
        bound = farthest_kept->first;
      }
    }
    const size_t listed = std::min(s.found.size(), static_cast<size_t>(max_list_));
    const auto end_listed = s.found.begin() + static_cast<std::ptrdiff_t>(listed);
    if (listed < s.found.size()) std::nth_element(s.found.begin(), end_listed, s.found.end(), nearer);
    for (size_t m = listed; m < s.found.size(); ++m) unlisted = std::min(unlisted, s.found[m].first);
    grid_.reach[v] = std::clamp(unlisted - radius_, 0.0, std::numeric_limits<double>::max());
    store_entries(s, out, centre, listed);
  }

  // Writes a voxel's first `listed` found faces as its entries. Each listed face's near bound: no
  // point within pad of the voxel is nearer to it than its distance from the centre less
  // `radius`, than the gap between the voxel's box and the face's box, or than the voxel's box's
  // gap from the face's plane; each less pad again for rounding.
  void store_entries(Scratch& s, Part& out, const Vec3& centre, size_t listed) const {
    const auto end_listed = s.found.begin() + static_cast<std::ptrdiff_t>(listed);
    const Vec3 half(0.5 * voxel_ + pad_), low = centre - half, high = centre + half;
    for (auto it = s.found.begin(); it != end_listed; ++it) {
      const Box3& box = boxes_[it->second];
      const FacePlane& plane = planes_[it->second];
      double near = it->first - radius_;
      near = std::max(near, glm::length(glm::max(glm::max(box.lo - high, low - box.hi), Vec3(0.0))) - pad_);
      if (plane.planar) {
        const Vec3& a = mesh_.positions[mesh_.triangles[it->second][0]];
        near = std::max(near, std::abs(glm::dot(centre - a, plane.normal)) - glm::dot(half, glm::abs(plane.normal)) - pad_);
      }
      it->first = std::max(near, 0.0);
    }
    std::sort(s.found.begin(), end_listed, nearer);
    out.counts.push_back(static_cast<uint32_t>(listed));
    // Groups by label (a counting sort, which keeps each group nearest first).
    s.label_count.assign(labels_, 0);
    for (size_t m = 0; m < listed; ++m) ++s.label_count[label(s.found[m].second)];
    uint32_t groups = 0, offset_in_list = 0;
    for (uint32_t l = 0; l < labels_; ++l) {
      if (s.label_count[l] == 0) continue;
      ++groups;
      out.group_labels.push_back(l);
      out.group_sizes.push_back(s.label_count[l]);
      const uint32_t size = s.label_count[l];
      s.label_count[l] = offset_in_list;  // now where the group starts
      offset_in_list += size;
    }
    out.group_counts.push_back(groups);
    const size_t base = out.faces.size();
    out.faces.resize(base + listed);
    out.near.resize(base + listed);
    for (size_t m = 0; m < listed; ++m) {
      const double near = s.found[m].first;
      float rounded = static_cast<float>(near);
      if (static_cast<double>(rounded) > near) rounded = std::nextafter(rounded, 0.0f);
      const size_t at = base + s.label_count[label(s.found[m].second)]++;
      out.faces[at] = s.found[m].second;
      out.near[at] = rounded;
    }
  }

  // A far voxel's reach is the nearest face's distance from its centre, less the radius: bounding
  // it by `far` alone, between widely spaced elements (the fruit), bounded points many times
  // nearer than they are, and left the kernel's bounds too low to prune candidates.
  void reach_far_voxels() {
    std::vector<int64_t> far_voxels;
    for (const Part& part : parts_) far_voxels.insert(far_voxels.end(), part.far_voxels.begin(), part.far_voxels.end());
    if (far_voxels.empty()) return;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, far_voxels.size(), 256), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t m = range.begin(); m != range.end(); ++m) {
        const int64_t w = far_voxels[m];
        const int i = static_cast<int>(w % n_.x), j = static_cast<int>((w / n_.x) % n_.y),
                  k = static_cast<int>(w / (int64_t{n_.x} * n_.y));
        const Vec3 centre = grid_.origin + (Vec3(i, j, k) + 0.5) * voxel_;
        const ClosestPoint nearest = bvh_.closest_point(centre);
        grid_.reach[w] = std::max(grid_.reach[w], nearest.distance - radius_);
        grid_.nearest_face[w] = nearest.face;
      }
    });
  }

  // Part p holds voxels [p n.x, (p + 1) n.x) in order; each is copied into place at offsets
  // summed over the parts before it, in parallel (appending in turn to arrays regrown as they
  // fill copies large grids several times over, one thread at a time).
  void join_parts() {
    std::vector<size_t> entry_offset(parts_.size() + 1, 0), group_offset(parts_.size() + 1, 0);
    for (size_t p = 0; p < parts_.size(); ++p) {
      entry_offset[p + 1] = entry_offset[p] + parts_[p].faces.size();
      group_offset[p + 1] = group_offset[p] + parts_[p].group_sizes.size();
    }
    grid_.start.assign(count_ + 1, 0);
    grid_.group_start.assign(count_ + 1, 0);
    resize_populated(grid_.faces, entry_offset.back());
    resize_populated(grid_.near, entry_offset.back());
    resize_populated(grid_.groups, group_offset.back());
    tbb::parallel_for(size_t{0}, parts_.size(), [&](size_t p) {
      Part& part = parts_[p];
      const size_t first_voxel = p * static_cast<size_t>(n_.x), first_group = group_offset[p];
      auto entries = static_cast<uint32_t>(entry_offset[p]);
      auto groups = static_cast<uint32_t>(first_group);
      for (size_t m = 0; m < part.counts.size(); ++m) {
        entries += part.counts[m];
        groups += part.group_counts[m];
        grid_.start[first_voxel + m + 1] = entries;
        grid_.group_start[first_voxel + m + 1] = groups;
      }
      auto group_first = static_cast<uint32_t>(entry_offset[p]);
      for (size_t g = 0; g < part.group_sizes.size(); ++g) {
        const uint32_t end = group_first + part.group_sizes[g];
        grid_.groups[first_group + g] = {group_first, end, part.group_labels[g], part.near[group_first - entry_offset[p]]};
        group_first = end;
      }
      std::copy(part.faces.begin(), part.faces.end(), grid_.faces.begin() + static_cast<std::ptrdiff_t>(entry_offset[p]));
      std::copy(part.near.begin(), part.near.end(), grid_.near.begin() + static_cast<std::ptrdiff_t>(entry_offset[p]));
      part = Part{};  // released as it is copied
    });
  }

  const TriMesh& mesh_;
  const double list_margin_, far_;
  const int max_list_;
  const std::vector<uint32_t>& face_groups_;
  const uint32_t labels_;
  const std::vector<FaceSphere> spheres_;
  const std::vector<FacePlane> planes_;
  const FaceBvh bvh_;
  NearFaceGrid grid_;
  glm::ivec3 n_{0};
  int64_t count_ = 0;
  double voxel_ = 0.0, pad_ = 0.0, radius_ = 0.0, slack_ = 0.0;
  std::vector<uint32_t> bucket_start_, bucket_;
  std::vector<Box3> boxes_;
  std::vector<Part> parts_;
};

}  // namespace

NearFaceGrid build_near_face_grid(const TriMesh& mesh, double voxel, double margin, double list_margin, double far,
                                  int max_list, int64_t max_voxels, const std::vector<uint32_t>& face_groups) {
  return NearFaceGridBuilder(mesh, list_margin, far, max_list, face_groups).build(voxel, margin, max_voxels);
}

}  // namespace meshquilt
