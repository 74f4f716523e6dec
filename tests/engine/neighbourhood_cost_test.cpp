// The neighbourhood_cost kernel (the search of texture synthesis on surfaces) on both back ends,
// against this file's own bilinear, wrapped read of the sample in double.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/error.h"
#include "device.h"
#include "neighbourhood_cost.h"
#include "support/backends.h"

namespace meshquilt {
namespace {

using kernels::neighbourhood_cost_layout::NeighbourhoodCandidate;
using kernels::neighbourhood_cost_layout::NeighbourhoodNeighbour;
using kernels::neighbourhood_cost_layout::NeighbourhoodVisit;

class NeighbourhoodCostTest : public test::BackendTest {};

struct Sample {
  int width, height;
  std::vector<glm::vec4> rgb;

  // Pixel (i, j) covers [i, i + 1) x [j, j + 1), its colour at its centre; between centres the
  // four around blend linearly, and the sample repeats in both directions.
  glm::dvec3 read(double x, double y) const {
    const double u = x - 0.5, v = y - 0.5;
    const double i = std::floor(u), j = std::floor(v);
    const auto at = [&](double a, double b) {
      const int p = static_cast<int>(a - width * std::floor(a / width));
      const int q = static_cast<int>(b - height * std::floor(b / height));
      return glm::dvec3(rgb[q * width + p]);
    };
    const double s = u - i, t = v - j;
    return (1 - s) * (1 - t) * at(i, j) + s * (1 - t) * at(i + 1, j) + (1 - s) * t * at(i, j + 1) + s * t * at(i + 1, j + 1);
  }
};

Sample random_sample(int width, int height, std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Sample sample{width, height, {}};
  for (int k = 0; k < width * height; ++k) sample.rgb.emplace_back(unit(rng), unit(rng), unit(rng), 0.0f);
  return sample;
}

TEST_P(NeighbourhoodCostTest, MatchesABruteForceReadOfTheSampleOnRandomNeighbourhoods) {
  std::mt19937 rng(7);
  for (const auto& [width, height] : {std::pair{5, 3}, std::pair{64, 48}, std::pair{1024, 7}}) {
    const Sample sample = random_sample(width, height, rng);
    NeighbourhoodCost cost(device(), width, height, sample.rgb);
    std::uniform_real_distribution<double> offset(-12.0, 12.0), unit(0.0, 1.0);
    NeighbourhoodBatch batch;
    for (uint32_t v = 0; v < 30; ++v) {
      const auto first = static_cast<uint32_t>(batch.neighbours.size());
      const int count = static_cast<int>(rng() % 60);
      for (int k = 0; k < count; ++k)
        batch.neighbours.push_back({glm::vec4(offset(rng), offset(rng), unit(rng), 0.0),
                                    glm::vec4(unit(rng), unit(rng), unit(rng), 0.0)});
      batch.visits.push_back({first, static_cast<uint32_t>(count), 0, 0});
      for (int k = 0; k < 25; ++k)
        batch.candidates.push_back({glm::ivec2(static_cast<int>(rng() % width), static_cast<int>(rng() % height)),
                                    glm::vec2(unit(rng), unit(rng)), v, 0});
    }
    const std::vector<float> costs = cost.score(batch);
    ASSERT_EQ(costs.size(), batch.candidates.size());
    for (size_t c = 0; c < costs.size(); ++c) {
      const NeighbourhoodCandidate& candidate = batch.candidates[c];
      const NeighbourhoodVisit& visit = batch.visits[candidate.visit];
      double expected = 0.0, weights = 0.0;
      for (uint32_t k = visit.first; k < visit.first + visit.count; ++k) {
        const NeighbourhoodNeighbour& n = batch.neighbours[k];
        const glm::dvec3 s = sample.read(candidate.pixel.x + double(candidate.fraction.x) + n.offset.x,
                                         candidate.pixel.y + double(candidate.fraction.y) + n.offset.y);
        const glm::dvec3 d = glm::dvec3(n.colour) - s;
        expected += n.offset.z * (d.x * d.x + d.y * d.y + d.z * d.z);
        weights += n.offset.z;
      }
      // The margin the painter allows float costs: 1e-4 of the cost plus the summed weight.
      EXPECT_NEAR(costs[c], expected, 1e-5 * (expected + weights) + 1e-9) << width << " x " << height << " #" << c;
    }
  }
}

TEST_P(NeighbourhoodCostTest, RefusesWhatWouldReadOutsideItsBuffers) {
  std::mt19937 rng(3);
  const Sample sample = random_sample(4, 4, rng);
  EXPECT_THROW(NeighbourhoodCost(device(), 4, 5, sample.rgb), InputError);
  NeighbourhoodCost cost(device(), 4, 4, sample.rgb);
  NeighbourhoodBatch batch;
  batch.neighbours.push_back({glm::vec4(1, 0, 1, 0), glm::vec4(0.5f)});
  batch.visits.push_back({0, 1, 0, 0});
  batch.candidates.push_back({glm::ivec2(3, 3), glm::vec2(0.5f), 0, 0});
  EXPECT_EQ(cost.score(batch).size(), 1u);
  batch.candidates[0].pixel.x = 4;
  EXPECT_THROW(cost.score(batch), InputError);
  batch.candidates[0].pixel.x = 0;
  batch.candidates[0].visit = 1;
  EXPECT_THROW(cost.score(batch), InputError);
  batch.candidates[0].visit = 0;
  batch.visits[0].count = 2;
  EXPECT_THROW(cost.score(batch), InputError);
  batch.visits[0].count = 1;
  batch.candidates[0].fraction.y = 1.0f;
  EXPECT_THROW(cost.score(batch), InputError);
}

MESHQUILT_ON_BACKENDS(NeighbourhoodCostTest);

}  // namespace
}  // namespace meshquilt
