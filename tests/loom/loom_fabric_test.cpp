#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include "loom/loom_fabric.h"
#include "loom_designs.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "spatial/intersecting_pairs.h"
#include <glm/geometric.hpp>

#include "swatch/weave.h"

namespace meshquilt {
namespace {

// Exemplars as different tools would make them: other tube sides, samples along the yarn,
// radius and pitch.
std::vector<ExemplarProfiles> exemplars(int per_pitch, int sides) {
  struct Made {
    WeavePattern pattern;
    int repeats, sides, segments;
    double pitch, radius;
  };
  const Made made[3] = {{twill_pattern(1, 1), 4, 8, 6, 1.0, 0.22},
                        {twill_pattern(2, 2), 2, 5, 4, 1.0, 0.2},
                        {satin_pattern(5, 2), 2, 12, 9, 2.0, 0.5}};
  std::vector<ExemplarProfiles> out;
  int n = 0;
  for (const Made& m : made) {
    WeaveOptions o;
    o.pattern = m.pattern;
    o.warps = m.repeats * m.pattern.warps;
    o.wefts = m.repeats * m.pattern.wefts;
    o.sides = m.sides;
    o.segments_per_pitch = m.segments;
    o.pitch = m.pitch;
    o.yarn_radius = m.radius;
    o.amplitude = 0.3 * m.pitch;
    const TriMesh mesh = make_weave(o);
    const std::string name = "exemplar " + std::to_string(n++);
    out.push_back(profile_exemplar(mesh, register_exemplar(mesh, name), per_pitch, sides, name));
  }
  return out;
}

// The patterns the exemplars were registered with, and the structured assignment from them.
LoomAssignment assigned(const LoomDesign& design, const std::vector<ExemplarProfiles>& ex,
                        const AssignmentOptions& options = {}) {
  std::vector<WeavePattern> patterns;
  for (const ExemplarProfiles& e : ex) patterns.push_back(e.weave.pattern);
  return assign_blocks(design, patterns, options);
}

// Which yarn is on top at each crossing, read from the mesh: a ray cast down at the crossing
// against the two yarns that cross there (warp c, weft r); the higher hit's element.
std::optional<bool> warp_on_top(const TriMesh& mesh, const std::vector<std::vector<int32_t>>& faces_of,
                                const LoomGrid& grid, int r, int c) {
  const glm::dvec2 p = grid.origin + static_cast<double>(r) * grid.row_step + static_cast<double>(c) * grid.column_step;
  double best = -1e300;
  std::optional<bool> warp;
  for (int32_t element : {c, grid.columns + r})
    for (int32_t f : faces_of[element]) {
      const Tri& t = mesh.triangles[f];
      const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &q = mesh.positions[t[2]];
      const double d = (b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y);
      if (std::abs(d) < 1e-15) continue;
      const double u = ((p.x - a.x) * (q.y - a.y) - (q.x - a.x) * (p.y - a.y)) / d;
      const double v = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / d;
      if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
      const double z = a.z + u * (b.z - a.z) + v * (q.z - a.z);
      if (z > best) {
        best = z;
        warp = element == c;
      }
    }
  return warp;
}

TEST(LoomFabric, ThreeRegionsFromThreeExemplarsWeaveTheDesign) {
  const LoomDesign design = three_regions(32);
  const std::vector<ExemplarProfiles> ex = exemplars(8, 8);
  const LoomAssignment assignment = assigned(design, ex);
  const LoomFabric fabric = weave_fabric(design, assignment, ex);
  const TriMesh& mesh = fabric.mesh;
  ASSERT_EQ(mesh.elements.size(), mesh.num_faces());

  // Closed, outward tubes, one per yarn.
  const SurfaceReport report = inspect_surface(mesh);
  EXPECT_TRUE(report.closed_manifold());
  EXPECT_EQ(report.components, design.rows + design.columns);

  // The right yarn on top at every crossing, read from the geometry.
  std::vector<std::vector<int32_t>> faces_of(static_cast<size_t>(design.rows + design.columns));
  for (size_t f = 0; f < mesh.num_faces(); ++f) faces_of[mesh.elements[f]].push_back(static_cast<int32_t>(f));
  int right = 0;
  for (int r = 0; r < design.rows; ++r)
    for (int c = 0; c < design.columns; ++c) {
      const std::optional<bool> warp = warp_on_top(mesh, faces_of, fabric.grid, r, c);
      right += warp && *warp == design.at(r, c);
    }
  EXPECT_GE(right, design.rows * design.columns * 995 / 1000);

  // Each yarn runs the design's whole extent.
  for (int e = 0; e < design.rows + design.columns; ++e) {
    double lo = 1e300, hi = -1e300;
    for (int32_t f : faces_of[e])
      for (int32_t v : mesh.triangles[f]) {
        const double run = e < design.columns ? mesh.positions[v].y : mesh.positions[v].x;
        lo = std::min(lo, run);
        hi = std::max(hi, run);
      }
    EXPECT_GE(hi - lo, 0.99 * (e < design.columns ? design.rows : design.columns)) << "yarn " << e;
  }

  // No two yarns pass through each other.
  const std::vector<FacePair> pairs = intersecting_face_pairs(mesh, mesh.elements, IntersectionScope::different_elements);
  EXPECT_TRUE(pairs.empty()) << pairs.size() << " face pairs, the first between yarns "
                             << (pairs.empty() ? -1 : mesh.elements[pairs[0].first]) << " and "
                             << (pairs.empty() ? -1 : mesh.elements[pairs[0].second]);
}

// A repeating design's fabric continues into its copy: each yarn's last ring is its first moved
// by the fabric's extent along its run.
TEST(LoomFabric, ARepeatingDesignEndsEachYarnAsItStarts) {
  LoomDesign design{8, 12, {}};
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 12; ++c) design.warp_over.push_back(c < 4 ? (c + r) % 2 == 0 : (c + r) % 4 < 2);
  const std::vector<ExemplarProfiles> ex = exemplars(4, 6);
  AssignmentOptions options;
  options.periodic = true;
  const LoomAssignment assignment = assigned(design, ex, options);
  std::vector<WeavePattern> patterns;
  for (const ExemplarProfiles& e : ex) patterns.push_back(e.weave.pattern);
  EXPECT_GE(score_assignment(design, patterns, assignment, true).correct, 1.0);
  const LoomFabric fabric = weave_fabric(design, assignment, ex, {}, true);
  const TriMesh& mesh = fabric.mesh;
  const int sides = 6;
  size_t first = 0;
  for (int yarn = 0; yarn < design.rows + design.columns; ++yarn) {
    const bool warp = yarn < design.columns;
    const size_t stations = static_cast<size_t>((warp ? design.rows : design.columns) * 4 + 1);
    const Vec3 shift = warp ? Vec3(0.0, -design.rows * 1.0, 0.0) : Vec3(design.columns * 1.0, 0.0, 0.0);
    for (int k = 0; k < sides; ++k) {
      const Vec3 a = mesh.positions[first + k] + shift, b = mesh.positions[first + (stations - 1) * sides + k];
      EXPECT_LT(glm::length(a - b), 1e-9) << "yarn " << yarn << ", corner " << k;
    }
    first += stations * sides + 2;
  }
  const std::vector<FacePair> pairs = intersecting_face_pairs(mesh, mesh.elements, IntersectionScope::different_elements);
  EXPECT_TRUE(pairs.empty()) << pairs.size() << " face pairs";
}

TEST(LoomFabric, StreamedFileEqualsTheMeshWrittenWhole) {
  const LoomDesign design = three_regions(12);
  const std::vector<ExemplarProfiles> ex = exemplars(4, 6);
  const LoomAssignment assignment = assigned(design, ex);
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "meshquilt_loom_stream";
  std::filesystem::create_directories(folder);
  const LoomFabric whole = weave_fabric(design, assignment, ex);
  write_mesh(whole.mesh, folder / "whole.ply");
  const LoomFabricFile streamed = write_fabric_ply(design, assignment, ex, folder / "streamed.ply");
  EXPECT_EQ(streamed.faces, whole.mesh.num_faces());
  EXPECT_EQ(streamed.vertices, whole.mesh.num_vertices());
  const auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(folder / "streamed.ply"), bytes(folder / "whole.ply"));
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace meshquilt
