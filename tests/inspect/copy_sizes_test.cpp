#include <gtest/gtest.h>

#include "inspect/copy_sizes.h"
#include "mesh/topology.h"
#include "swatch/chainmail.h"

namespace meshquilt {
namespace {

// Copies of a mail's rings at known sizes: each ring i scaled by 1 + i / 10 about its centre and
// moved; the distribution is read back exactly. A ring with a vertex too many is not a copy.
TEST(CopySizes, ReadsBackTheScalesOfWholeCopies) {
  ChainmailOptions o;
  o.rows = 4;
  o.columns = 5;
  const TriMesh swatch = make_chainmail(o);
  const std::vector<TriMesh> rings = split_elements(swatch);
  const double unit = 2.5;
  std::vector<TriMesh> copies;
  std::vector<double> scales;
  for (size_t i = 0; i < rings.size(); ++i) {
    TriMesh copy = rings[i];
    Vec3 mean(0.0);
    for (const Vec3& p : copy.positions) mean += p / static_cast<double>(copy.positions.size());
    const double s = 1.0 + 0.1 * static_cast<double>(i % 10);
    scales.push_back(s);
    for (Vec3& p : copy.positions) p = (p - mean) * (s * unit) + Vec3(3.0 * i, 0.0, 1.0);
    copies.push_back(copy);
  }
  TriMesh extra = rings[0];  // a stitched element: one vertex more than its source
  extra.positions.push_back(extra.positions[0] * 9.0);
  extra.triangles.push_back({0, 1, static_cast<int32_t>(extra.positions.size()) - 1});
  copies.push_back(extra);
  TriMesh output = join_elements(copies);
  output.sources.resize(output.num_faces());
  for (size_t f = 0; f < output.num_faces(); ++f)
    output.sources[f] = output.elements[f] < static_cast<int32_t>(rings.size()) ? output.elements[f] : 0;
  const CopySizes sizes = copy_sizes(output, rings, unit);
  EXPECT_EQ(sizes.copies, static_cast<int>(rings.size()));
  std::sort(scales.begin(), scales.end());
  const auto at = [&](double q) { return scales[std::min(scales.size() - 1, static_cast<size_t>(q * scales.size()))]; };
  EXPECT_NEAR(sizes.p10, at(0.1), 1e-9);
  EXPECT_NEAR(sizes.median, at(0.5), 1e-9);
  EXPECT_NEAR(sizes.p90, at(0.9), 1e-9);
}

}  // namespace
}  // namespace meshquilt
