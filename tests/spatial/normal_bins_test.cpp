// NormalBins against brute force: a bin's factor for a query never exceeds the normal term of
// any of its members, and it is tight enough to matter for normals that face away.
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

#include "spatial/normal_bins.h"

namespace meshquilt {
namespace {

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

TEST(NormalBins, FactorsNeverExceedAMembersNormalTerm) {
  std::mt19937 rng(5);
  std::vector<Vec3> normals;
  for (int i = 0; i < 2000; ++i) normals.push_back(random_unit(rng));
  normals.push_back({0.0, 0.0, 1.0});  // the poles and axes, where the octahedral map folds
  normals.push_back({0.0, 0.0, -1.0});
  normals.push_back({1.0, 0.0, 0.0});
  normals.push_back({0.0, -1.0, 0.0});
  for (int per_side : {1, 2, 4, 6}) {
    const NormalBins bins = bin_normals(normals, per_side);
    ASSERT_EQ(bins.bin_of.size(), normals.size());
    ASSERT_LE(bins.size(), static_cast<size_t>(per_side * per_side));
    std::vector<double> factors(bins.size());
    for (int q = 0; q < 300; ++q) {
      const Vec3 n = q < 4 ? normals[normals.size() - 1 - q] : random_unit(rng);
      bins.factor_bounds(n, factors.data());
      for (size_t i = 0; i < normals.size(); ++i) {
        ASSERT_LT(bins.bin_of[i], bins.size());
        ASSERT_LE(factors[bins.bin_of[i]], 1.0 + glm::length(n - normals[i])) << per_side << " query " << q << " member " << i;
      }
    }
  }
}

TEST(NormalBins, BinsFacingAwayAreBoundedAwayFromOne) {
  // Normals within 10 degrees of +z, and a few within 10 degrees of -z: their bins are tight.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> angle(0.0, 10.0 * M_PI / 180.0), turn(0.0, 2.0 * M_PI);
  std::vector<Vec3> normals;
  for (int i = 0; i < 200; ++i) {
    const double a = angle(rng), t = turn(rng);
    const double z = i % 4 == 0 ? -std::cos(a) : std::cos(a);
    normals.emplace_back(std::sin(a) * std::cos(t), std::sin(a) * std::sin(t), z);
  }
  const NormalBins bins = bin_normals(normals, 4);
  std::vector<double> factors(bins.size());
  bins.factor_bounds({0.0, 0.0, 1.0}, factors.data());
  for (size_t i = 0; i < normals.size(); ++i) {
    const double exact = 1.0 + glm::length(Vec3(0.0, 0.0, 1.0) - normals[i]);
    if (normals[i].z < 0.0) EXPECT_GT(factors[bins.bin_of[i]], 2.6) << i;  // members are at least 2.99
    else EXPECT_LE(factors[bins.bin_of[i]], exact);
  }
}

}  // namespace
}  // namespace meshquilt
