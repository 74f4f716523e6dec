// NearFaceGrid against brute force over every face: for points anywhere in (and around) a voxel,
// no unlisted face is nearer than the voxel's reach and no listed face nearer than its entry.
#include <gtest/gtest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "spatial/near_face_grid.h"

namespace meshquilt {
namespace {

// Independent reference: the minimum of the distance to the plane (where the projection falls
// inside) and to the three edges, sampled with no region tests.
double reference_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  double best = std::numeric_limits<double>::infinity();
  const Vec3 v[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const Vec3 s = v[e], d = v[(e + 1) % 3] - v[e];
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - s, d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(p - (s + t * d)));
  }
  const Vec3 n = glm::cross(b - a, c - a);
  const double n2 = glm::dot(n, n);
  if (n2 > 0.0) {
    const Vec3 q = p - glm::dot(p - a, n) / n2 * n;
    if (glm::dot(glm::cross(b - q, c - q), n) >= 0 && glm::dot(glm::cross(c - q, a - q), n) >= 0 &&
        glm::dot(glm::cross(a - q, b - q), n) >= 0)
      best = std::min(best, glm::length(p - q));
  }
  return best;
}

TriMesh random_soup(std::mt19937& rng, int faces) {
  std::uniform_real_distribution<double> x(0.0, 4.0), y(0.0, 3.0), z(0.0, 0.5), size(-0.3, 0.3);
  TriMesh mesh;
  for (int f = 0; f < faces; ++f) {
    const Vec3 a(x(rng), y(rng), z(rng));
    Vec3 b = a + Vec3(size(rng), size(rng), size(rng)), c = a + Vec3(size(rng), size(rng), size(rng));
    if (f % 17 == 0) c = a + 0.5 * (b - a);                  // zero area
    if (f % 29 == 0) c = a + Vec3(1.5, 0.2, 0.0);            // spans many voxels
    const auto base = static_cast<int32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

void check_against_brute_force(const TriMesh& mesh, const NearFaceGrid& grid, std::mt19937& rng, int samples,
                               double decided_share) {
  const Vec3 span = Vec3(grid.size) * grid.voxel;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int listed_answers = 0;
  for (int s = 0; s < samples; ++s) {
    const Vec3 q = grid.origin + Vec3(unit(rng), unit(rng), unit(rng)) * span;
    const int64_t v = grid.voxel_of(q);
    ASSERT_GE(v, 0);
    const std::set<uint32_t> listed(grid.faces.begin() + grid.start[v], grid.faces.begin() + grid.start[v + 1]);
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      const Tri& t = mesh.triangles[f];
      const double d = reference_distance(q, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
      nearest = std::min(nearest, d);
      if (!listed.count(static_cast<uint32_t>(f))) ASSERT_GE(d, grid.reach[v] - 1e-12) << "unlisted face " << f;
    }
    for (uint32_t k = grid.start[v]; k < grid.start[v + 1]; ++k) {
      const Tri& t = mesh.triangles[grid.faces[k]];
      ASSERT_GE(reference_distance(q, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]),
                grid.near[k] - 1e-12);
    }
    // The groups partition the list, each nearest first.
    uint32_t next = grid.start[v];
    for (uint32_t g = grid.group_start[v]; g < grid.group_start[v + 1]; ++g) {
      const FaceGroup& group = grid.groups[g];
      ASSERT_EQ(group.first, next);
      ASSERT_LT(group.first, group.end);
      ASSERT_EQ(group.near, grid.near[group.first]);
      for (uint32_t k = group.first + 1; k < group.end; ++k) ASSERT_LE(grid.near[k - 1], grid.near[k]);
      next = group.end;
    }
    ASSERT_EQ(next, grid.start[v + 1]);
    // The faces' box bounds them (the kernel's bound outside the grid).
    const double outside = glm::length(glm::max(glm::max(grid.box_low - q, q - grid.box_high), Vec3(0.0)));
    EXPECT_GE(nearest, outside - 1e-12);
    if (nearest < grid.reach[v]) ++listed_answers;
  }
  // The lists are not empty promises: for a share of the samples they decide the nearest face.
  EXPECT_GT(listed_answers, decided_share * samples);
}

TEST(NearFaceGrid, ReachAndEntriesHoldEverywhereOnARandomSoup) {
  std::mt19937 rng(5);
  const TriMesh mesh = random_soup(rng, 300);
  const NearFaceGrid grid = build_near_face_grid(mesh, 0.1, 0.3, 0.15, 0.6, 64);
  EXPECT_EQ(grid.start.size(), static_cast<size_t>(grid.size.x) * grid.size.y * grid.size.z + 1);
  EXPECT_EQ(grid.faces.size(), grid.near.size());
  check_against_brute_force(mesh, grid, rng, 3000, 0.25);
}

// Grouped by labels, a voxel lists the same faces with the same bounds, one group per label
// in ascending order.
TEST(NearFaceGrid, GroupsPartitionEachListByLabel) {
  std::mt19937 rng(7);
  const TriMesh mesh = random_soup(rng, 300);
  std::vector<uint32_t> labels(mesh.num_faces());
  for (size_t f = 0; f < labels.size(); ++f) labels[f] = static_cast<uint32_t>((f * 7) % 5);
  const NearFaceGrid plain = build_near_face_grid(mesh, 0.1, 0.3, 0.15, 0.6, 64);
  const NearFaceGrid grouped = build_near_face_grid(mesh, 0.1, 0.3, 0.15, 0.6, 64, int64_t{1} << 18, labels);
  ASSERT_EQ(grouped.start, plain.start);
  ASSERT_EQ(grouped.reach, plain.reach);
  size_t several = 0;
  for (size_t v = 0; v + 1 < plain.start.size(); ++v) {
    std::multiset<std::pair<uint32_t, float>> a, b;
    for (uint32_t k = plain.start[v]; k < plain.start[v + 1]; ++k) a.insert({plain.faces[k], plain.near[k]});
    for (uint32_t k = grouped.start[v]; k < grouped.start[v + 1]; ++k) b.insert({grouped.faces[k], grouped.near[k]});
    ASSERT_EQ(a, b) << "voxel " << v;
    ASSERT_LE(plain.group_start[v + 1] - plain.group_start[v], 1u);  // one group without labels
    for (uint32_t g = grouped.group_start[v]; g < grouped.group_start[v + 1]; ++g) {
      if (g > grouped.group_start[v]) ASSERT_LT(grouped.groups[g - 1].label, grouped.groups[g].label);
      for (uint32_t k = grouped.groups[g].first; k < grouped.groups[g].end; ++k)
        ASSERT_EQ(labels[grouped.faces[k]], grouped.groups[g].label);
    }
    several += grouped.group_start[v + 1] - grouped.group_start[v] > 1;
  }
  EXPECT_GT(several, 100u);
  check_against_brute_force(mesh, grouped, rng, 1500, 0.25);
}

TEST(NearFaceGrid, ShortListsAndCoarsenedVoxelsStayValid) {
  std::mt19937 rng(6);
  const TriMesh mesh = random_soup(rng, 300);
  // Lists capped at 4 faces, and voxels coarsened to fit 2,000.
  const NearFaceGrid grid = build_near_face_grid(mesh, 0.01, 0.3, 0.5, 1.0, 4, 2000);
  EXPECT_LE(static_cast<int64_t>(grid.size.x) * grid.size.y * grid.size.z, 2000);
  EXPECT_GT(grid.voxel, 0.01);
  for (size_t v = 0; v + 1 < grid.start.size(); ++v) ASSERT_LE(grid.start[v + 1] - grid.start[v], 4u);
  check_against_brute_force(mesh, grid, rng, 1500, 0.1);
}

// A crowded voxel (more faces within its list radius than a list holds) lists the faces nearest
// its centre, and its reach comes from the next nearest face: lists short enough to be cut many
// times over while the build searches, against distances from the centre to every face.
TEST(NearFaceGrid, CrowdedVoxelsListTheNearestFacesAndReachTheNextOne) {
  std::mt19937 rng(9);
  const TriMesh mesh = random_soup(rng, 400);
  const int max_list = 6;
  const double list_margin = 0.8;
  const double far = 1.0;
  const NearFaceGrid grid = build_near_face_grid(mesh, 0.1, 0.3, list_margin, far, max_list);
  const double half_diagonal = 0.5 * std::sqrt(3.0) * grid.voxel;
  const int64_t voxels = static_cast<int64_t>(grid.size.x) * grid.size.y * grid.size.z;
  int crowded = 0;
  for (int64_t v = 0; v < voxels; v += 7) {
    const int64_t i = v % grid.size.x, j = (v / grid.size.x) % grid.size.y, k = v / (int64_t{grid.size.x} * grid.size.y);
    const Vec3 centre = grid.origin + (Vec3(i, j, k) + 0.5) * grid.voxel;
    std::vector<double> distance(mesh.num_faces());
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      const Tri& t = mesh.triangles[f];
      distance[f] = reference_distance(centre, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    }
    std::vector<double> sorted = distance;
    std::sort(sorted.begin(), sorted.end());
    // Near enough to list (blocks of 2 x 2 x 2 voxels past `far` list none), and more faces
    // than a list holds within the list radius: the nearest face's distance, the voxel's
    // diagonal and the margin.
    if (sorted[0] > far - 2.0 * half_diagonal) continue;
    if (!(sorted[max_list] < sorted[0] + 2.0 * half_diagonal + list_margin - 1e-6)) continue;
    ++crowded;
    ASSERT_EQ(grid.start[v + 1] - grid.start[v], static_cast<uint32_t>(max_list)) << "voxel " << v;
    const std::set<uint32_t> listed(grid.faces.begin() + grid.start[v], grid.faces.begin() + grid.start[v + 1]);
    double farthest_listed = 0.0, nearest_unlisted = std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      if (listed.count(static_cast<uint32_t>(f))) farthest_listed = std::max(farthest_listed, distance[f]);
      else nearest_unlisted = std::min(nearest_unlisted, distance[f]);
    }
    ASSERT_LE(farthest_listed, nearest_unlisted + 1e-12) << "voxel " << v;
    // Less the half diagonal and the walls' padding (about 2e-6 voxels), no more.
    const double expected = std::max(nearest_unlisted - half_diagonal, 0.0);
    ASSERT_LE(grid.reach[v], expected + 1e-12) << "voxel " << v;
    ASSERT_GE(grid.reach[v], expected - 1e-5 * grid.voxel) << "voxel " << v;
  }
  EXPECT_GT(crowded, 500);
}

// Over a flat sheet a voxel's entries are bounded by its box's gap from the sheet's plane
// (the height of its face nearest the sheet) at least, tighter than the centre's distance less
// the half diagonal.
TEST(NearFaceGrid, EntriesOverASheetAreBoundedByThePlane) {
  TriMesh sheet;
  const int n = 20;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) sheet.positions.emplace_back(0.1 * i, 0.1 * j, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t a = j * (n + 1) + i;
      sheet.triangles.push_back({a, a + 1, a + n + 2});
      sheet.triangles.push_back({a, a + n + 2, a + n + 1});
    }
  const NearFaceGrid grid = build_near_face_grid(sheet, 0.1, 0.5, 0.2, 1.0, 64);
  const double half_diagonal = 0.5 * std::sqrt(3.0) * grid.voxel;
  int checked = 0;
  for (int k = 0; k < grid.size.z; ++k) {
    const int64_t v = (static_cast<int64_t>(k) * grid.size.y + grid.size.y / 2) * grid.size.x + grid.size.x / 2;
    const Vec3 centre = grid.origin + (Vec3(grid.size.x / 2, grid.size.y / 2, k) + 0.5) * grid.voxel;
    const double lower_face = std::min(std::abs(centre.z - 0.5 * grid.voxel), std::abs(centre.z + 0.5 * grid.voxel));
    if (centre.z - 0.5 * grid.voxel <= 0.0 && centre.z + 0.5 * grid.voxel >= 0.0) continue;  // the sheet crosses it
    for (uint32_t e = grid.start[v]; e < grid.start[v + 1]; ++e) {
      ++checked;
      EXPECT_GE(grid.near[e], lower_face - 1e-5) << "voxel layer " << k;
      EXPECT_GT(grid.near[e], std::abs(centre.z) - half_diagonal + 0.01);
    }
  }
  EXPECT_GT(checked, 50);
}

// Between widely spaced elements (fruit) most voxels list nothing; their reach is the nearest
// face's distance less the voxel's half diagonal, a bound that stays close to the truth there
// rather than stopping at `far`.
TEST(NearFaceGrid, FarVoxelsAreBoundedByTheirNearestFace) {
  std::mt19937 rng(8);
  TriMesh mesh = random_soup(rng, 40);
  const size_t first = mesh.positions.size();
  for (size_t k = 0; k < first; ++k) {  // a second cluster far off
    mesh.positions.push_back(0.3 * mesh.positions[k] + Vec3(12.0, 0.0, 0.0));
    mesh.positions[k] *= 0.3;
  }
  for (size_t f = 0; f < 40; ++f) {
    const Tri t = mesh.triangles[f];
    const auto shift = static_cast<int32_t>(first);
    mesh.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  }
  const NearFaceGrid grid = build_near_face_grid(mesh, 0.2, 0.5, 0.2, 0.6, 16);
  const double half_diagonal = 0.5 * std::sqrt(3.0) * grid.voxel;
  const Vec3 span = Vec3(grid.size) * grid.voxel;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int far = 0;
  for (int s = 0; s < 2000; ++s) {
    const Vec3 q = grid.origin + Vec3(unit(rng), unit(rng), unit(rng)) * span;
    const int64_t v = grid.voxel_of(q);
    ASSERT_GE(v, 0);
    if (grid.start[v] != grid.start[v + 1]) continue;
    ++far;
    double nearest = std::numeric_limits<double>::infinity();
    for (const Tri& t : mesh.triangles)
      nearest = std::min(nearest, reference_distance(q, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
    ASSERT_GE(nearest, grid.reach[v] - 1e-12);
    EXPECT_GE(grid.reach[v], nearest - 2.0 * half_diagonal - 1e-9) << "at " << q.x << " " << q.y << " " << q.z;
  }
  EXPECT_GT(far, 1000);
  // A far voxel also names a face nearest its centre (a start for exact searches); others none.
  int named = 0;
  for (int64_t v = 0; v < static_cast<int64_t>(grid.reach.size()); ++v) {
    const int32_t f = grid.nearest_face[v];
    if (grid.start[v] != grid.start[v + 1]) {
      ASSERT_EQ(f, -1) << "voxel " << v;
      continue;
    }
    ASSERT_GE(f, 0) << "voxel " << v;
    ASSERT_LT(f, static_cast<int32_t>(mesh.num_faces()));
    const int64_t i = v % grid.size.x, j = (v / grid.size.x) % grid.size.y, k = v / (int64_t{grid.size.x} * grid.size.y);
    const Vec3 centre = grid.origin + (Vec3(i, j, k) + 0.5) * grid.voxel;
    const auto distance = [&](size_t g) {
      const Tri& t = mesh.triangles[g];
      return reference_distance(centre, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    };
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t g = 0; g < mesh.num_faces(); ++g) nearest = std::min(nearest, distance(g));
    ASSERT_LE(distance(static_cast<size_t>(f)), nearest + 1e-12) << "voxel " << v;
    ++named;
  }
  EXPECT_GT(named, 100);
}

TEST(NearFaceGrid, OutsideTheGridThereIsNoVoxel) {
  std::mt19937 rng(7);
  const TriMesh mesh = random_soup(rng, 20);
  const NearFaceGrid grid = build_near_face_grid(mesh, 0.2, 0.1, 0.2, 0.5);
  EXPECT_EQ(grid.voxel_of(grid.origin - Vec3(1e-9)), -1);
  EXPECT_EQ(grid.voxel_of(grid.origin + Vec3(grid.size) * grid.voxel + 1e-9), -1);
  EXPECT_EQ(grid.voxel_of(Vec3(NAN, 0.0, 0.0)), -1);
  EXPECT_EQ(grid.voxel_of(grid.origin), 0);
  Vec3 low(INFINITY), high(-INFINITY);
  for (const Vec3& p : mesh.positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  EXPECT_EQ(grid.box_low, low);
  EXPECT_EQ(grid.box_high, high);
}

}  // namespace
}  // namespace meshquilt
