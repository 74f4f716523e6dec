// Mesh quilting over base meshes end to end (Section 3.1 of the paper): coverage, heights,
// element integrity and intersections measured independently of the driver; scale; back ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <random>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include "device.h"
#include "inspect/coverage.h"
#include "inspect/ring_links.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "surface/surface_quilting.h"
#include "shell/shell_embedding.h"
#include "spatial/intersecting_pairs.h"
#include "swatch/chainmail.h"
#include "swatch/default_swatch.h"
#include "swatch/weave.h"
#include "support/backends.h"

namespace meshquilt {
namespace {

const std::filesystem::path kShared = MESHQUILT_SHARED_DIR;
const std::filesystem::path kSource = MESHQUILT_SOURCE_DIR;

struct SurfaceQuality {
  int elements = 0;
  int closed = 0;
  double intersecting_share = 0.0;  // faces in a pair of different elements / faces
  int self_intersecting_pairs = 0;  // face pairs of one element that share no vertex and meet
  double coverage = 0.0;            // base area with an output vertex within the cover radius
  double height_min = 0.0;          // bbox diagonals
  double height_max = 0.0;
};

double bbox_diagonal(const TriMesh& mesh) {
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

// Area-weighted sample points of the base; each counts as covered when an output vertex lies
// within `radius` (a hash grid of the output vertices, brute force inside each bucket).
double sampled_coverage(const TriMesh& base, const TriMesh& output, double radius, int samples) {
  std::vector<double> cumulative;
  double total = 0.0;
  for (const Tri& t : base.triangles) {
    total += 0.5 * glm::length(glm::cross(base.positions[t[1]] - base.positions[t[0]],
                                          base.positions[t[2]] - base.positions[t[0]]));
    cumulative.push_back(total);
  }
  std::unordered_map<int64_t, std::vector<Vec3>> grid;
  const auto key = [radius](int64_t x, int64_t y, int64_t z) { return (x * 73856093) ^ (y * 19349663) ^ (z * 83492791); };
  for (const Vec3& p : output.positions)
    grid[key(std::floor(p.x / radius), std::floor(p.y / radius), std::floor(p.z / radius))].push_back(p);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int covered = 0;
  for (int s = 0; s < samples; ++s) {
    const size_t f = std::lower_bound(cumulative.begin(), cumulative.end(), uniform(rng) * total) - cumulative.begin();
    const Tri& t = base.triangles[std::min(f, base.num_faces() - 1)];
    double a = uniform(rng), b = uniform(rng);
    if (a + b > 1.0) {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    const Vec3 p = (1.0 - a - b) * base.positions[t[0]] + a * base.positions[t[1]] + b * base.positions[t[2]];
    const int64_t x = std::floor(p.x / radius), y = std::floor(p.y / radius), z = std::floor(p.z / radius);
    bool hit = false;
    for (int64_t dz = -1; dz <= 1 && !hit; ++dz)
      for (int64_t dy = -1; dy <= 1 && !hit; ++dy)
        for (int64_t dx = -1; dx <= 1 && !hit; ++dx) {
          const auto it = grid.find(key(x + dx, y + dy, z + dz));
          if (it == grid.end()) continue;
          for (const Vec3& q : it->second)
            if (glm::distance(p, q) <= radius) {
              hit = true;
              break;
            }
        }
    covered += hit;
  }
  return static_cast<double>(covered) / samples;
}

// Cover radius from the swatch: half the median x-y extent of its elements, at the run's scale.
double swatch_cover_radius(const TriMesh& swatch, double unit) {
  std::vector<double> extents;
  for (const TriMesh& e : split_elements(swatch)) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const Vec3& p : e.positions) {
      lo = glm::min(lo, glm::dvec2(p));
      hi = glm::max(hi, glm::dvec2(p));
    }
    extents.push_back(std::max(hi.x - lo.x, hi.y - lo.y));
  }
  std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
  return 0.5 * extents[extents.size() / 2] * unit;
}

SurfaceQuality measure(const TriMesh& output, const TriMesh& base, double cover_radius) {
  SurfaceQuality q;
  for (const TriMesh& e : split_elements(output)) {
    ++q.elements;
    q.closed += inspect_surface(weld_vertices(e)).closed_manifold();
  }
  const FaceIntersections found = find_intersecting_faces(output, output.elements);
  const auto& pairs = found.different_elements;
  q.self_intersecting_pairs = static_cast<int>(found.same_element.size());
  std::vector<uint8_t> hit(output.num_faces(), 0);
  for (const auto& [a, b] : pairs) hit[a] = hit[b] = 1;
  q.intersecting_share = static_cast<double>(std::count(hit.begin(), hit.end(), 1)) / output.num_faces();
  q.coverage = sampled_coverage(base, output, cover_radius, 20000);
  const std::vector<double> heights = signed_heights(output.positions, base);
  q.height_min = *std::min_element(heights.begin(), heights.end());
  q.height_max = *std::max_element(heights.begin(), heights.end());
  return q;
}

struct SurfaceRun {
  TriMesh base;
  TriMesh output;
  SurfaceQuiltStats stats;
  double unit = 0.0;  // base units per swatch unit
  glm::dvec2 swatch_extent{0.0};  // the swatch's x-y sides, swatch units
};

enum class Embed { shell, original_shell, normal };

SurfaceRun run_surface(const TriMesh& raw_base, const TriMesh& swatch, double scale,
                       engine::BackendChoice backend = engine::BackendChoice::cpu, int max_patches = 0,
                       const std::vector<FieldConstraint>& constraints = {}, Embed embed = Embed::shell,
                       const std::function<void(SurfaceQuiltOptions&)>& adjust = {}) {
  SurfaceRun run;
  run.base = prepare_base(raw_base, "base");
  const BaseSurface surface(run.base);
  const GuidanceField field = interpolate_field(surface, constraints);
  auto device = engine::open_device(backend);
  SurfaceQuiltOptions options;
  options.scale = scale;
  options.max_patches = max_patches;
  // The shell map is synth's default; every bar here holds with it.
  if (embed != Embed::normal)
    options.embedding = [&](const BaseSurface& b, double height) {
      ShellEmbeddingOptions shell;
      shell.minimize_stretch = embed == Embed::shell;
      return std::unique_ptr<SurfaceEmbedding>(build_shell_embedding(*device, b, height, shell));
    };
  if (adjust) adjust(options);
  run.output = quilt_surface(swatch, run.base, field, *device, options, &run.stats).mesh;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const Vec3& p : swatch.positions) {
    lo = glm::min(lo, glm::dvec2(p));
    hi = glm::max(hi, glm::dvec2(p));
  }
  run.swatch_extent = hi - lo;
  run.unit = scale * surface.diagonal / std::max(run.swatch_extent.x, run.swatch_extent.y);
  return run;
}

// What a finished run must meet. The defaults are the bar of the curved-surface issue; a base that
// does not meet it yet gets its own, measured, bound (see docs/performance.md, known limits).
struct QualityBar {
  double max_dropped_share = 0.02;  // dropped open or intersecting elements / (kept + dropped)
  double max_folded_share = 0.02;   // dropped elements that passed through themselves / (kept + dropped)
  double min_height = -0.01;        // lowest vertex, signed, in bounding-box diagonals
  double min_coverage = 0.97;       // share of base samples with output over them
  double max_height_over = 0.01;    // highest vertex above the shell height, in diagonals
  double min_copies = 0.0;          // swatch copies the base holds at the run's scale
  double max_copies = 1e300;
};

// The issue's cases: a scale giving 50-200 swatch copies.
QualityBar issue_bar() {
  QualityBar bar;
  bar.min_copies = 50.0;
  bar.max_copies = 200.0;
  return bar;
}

void expect_quality(const SurfaceRun& run, const TriMesh& swatch, const char* what, const QualityBar& bar = {}) {
  const double base_area = [&] {
    double a = 0.0;
    for (const Tri& t : run.base.triangles)
      a += 0.5 * glm::length(glm::cross(run.base.positions[t[1]] - run.base.positions[t[0]],
                                        run.base.positions[t[2]] - run.base.positions[t[0]]));
    return a;
  }();
  const double diagonal = bbox_diagonal(run.base);
  const SurfaceQuality q = measure(run.output, run.base, swatch_cover_radius(swatch, run.unit));
  SCOPED_TRACE(what);
  // Swatch copies: the base's area over the swatch's x-y footprint at the run's scale.
  const double copies = base_area / (run.swatch_extent.x * run.swatch_extent.y * run.unit * run.unit);
  std::printf("%s: %.0f swatch copies, %d kept, %d dropped (%d folded), %d holes (%.2f%% of the area), coverage %.3f, heights "
              "%.4f..%.4f diagonals\n",
              what, copies, q.elements, run.stats.dropped_elements, run.stats.dropped_folded, run.stats.holes, 100.0 * run.stats.hole_area / base_area,
              q.coverage, q.height_min, q.height_max);
  EXPECT_GE(copies, bar.min_copies);
  EXPECT_LE(copies, bar.max_copies);
  EXPECT_LE(run.stats.hole_area, 0.01 * base_area);
  EXPECT_GE(q.coverage, bar.min_coverage);
  EXPECT_GE(q.height_min, bar.min_height);
  EXPECT_LE(q.height_max, run.stats.shell_height / diagonal + bar.max_height_over);
  EXPECT_GE(q.closed, 0.95 * q.elements);
  EXPECT_LE(q.intersecting_share, 0.01);
  // Copies joined end to end into one yarn count as the elements they were placed as.
  const int total = q.elements + run.stats.dropped_elements + run.stats.joined_elements;
  EXPECT_LE(run.stats.dropped_elements - run.stats.dropped_folded, bar.max_dropped_share * total);
  EXPECT_LE(run.stats.dropped_folded, bar.max_folded_share * total);
  EXPECT_EQ(q.self_intersecting_pairs, 0);
  EXPECT_EQ(run.output.sources.size(), run.output.num_faces());
}

TEST(SurfaceQuilting, ChainMailCoversTheShippedSphere) {
  const TriMesh swatch = make_chainmail(ChainmailOptions::small());
  const SurfaceRun run = run_surface(read_mesh(kSource / "data/sphere.off"), swatch, 0.3);
  expect_quality(run, swatch, "sphere + chain mail");
  EXPECT_GT(run.stats.patches, 5);
}

RingLinks links_of(const TriMesh& mesh) {
  int32_t elements = 0;
  for (int32_t e : mesh.elements) elements = std::max(elements, e + 1);
  return ring_links(mesh, mesh.elements, elements);
}

// The default job: the built-in mail over the shipped sphere at 0.2 must link as a plane does.
// Patches are windows of one layout whose seams continue by the mail's periods, placed on those
// periods, so rings registered by different patches pass through each other all round the
// cones (each patch with its own chart, or free seam translations: 57% and 87% linked to 3).
TEST(SurfaceQuilting, TheDefaultMailOverTheSphereLinksAsOnAPlane) {
  const TriMesh swatch = default_swatch();
  const SurfaceRun run = run_surface(read_mesh(kSource / "data/sphere.off"), swatch, 0.2);
  EXPECT_TRUE(run.stats.on_lattice);
  const RingLinks links = links_of(run.output);
  const RingLinks swatch_links = links_of(swatch);
  std::printf("sphere 0.2: %d rings, linked to >= 3 %.3f, largest piece %.3f, radius / asked %.3f, rejected %d\n",
              links.rings, links.linked_to_3_share, links.largest_piece_share,
              links.median_radius / (swatch_links.median_radius * run.unit), run.stats.merges.rejected_inputs);
  EXPECT_GE(links.linked_to_3_share, 0.95);
  EXPECT_GE(links.largest_piece_share, 0.99);
  EXPECT_LE(run.stats.merges.rejected_inputs, 0.05 * links.rings);
  EXPECT_EQ(run.stats.dropped_elements, 0);
  EXPECT_NEAR(links.median_radius / (swatch_links.median_radius * run.unit), 1.0, 0.05);
}

// Placed straight from the layout away from the cones, the pattern's rings are the rings the
// patch step places there: as many, linked as well (#61's bars: elements within 2%, linked to >= 3
// within 3 points, the largest piece within 8), and most rings need no patch. Both over the
// layout as first laid out: the fill's median would lay it out again.
class FilledPattern : public ::testing::TestWithParam<const char*> {};

TEST_P(FilledPattern, LinksAsThePatchStepDoes) {
  const std::string name = GetParam();
  const auto file = name == "sphere.off" ? kSource / "data/sphere.off" : kShared / "data/meshes" / name;
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const TriMesh swatch = default_swatch();
  const double scale = name == "sphere.off" ? 0.2 : 0.14;
  const SurfaceRun filled = run_surface(read_mesh(file), swatch, scale, engine::BackendChoice::cpu, 0, {}, Embed::shell,
                                        [](SurfaceQuiltOptions& o) { o.median_from_fill = false; });
  const SurfaceRun stepped = run_surface(read_mesh(file), swatch, scale, engine::BackendChoice::cpu, 0, {}, Embed::shell,
                                         [](SurfaceQuiltOptions& o) { o.fill_margin = 0.0; });
  const RingLinks a = links_of(filled.output), b = links_of(stepped.output);
  std::printf("%s: filled %d of %d rings in %d patches, linked to >= 3 %.3f, largest %.3f; stepped %d rings in %d "
              "patches, %.3f, %.3f\n",
              name.c_str(), filled.stats.filled_elements, a.rings, filled.stats.patches, a.linked_to_3_share,
              a.largest_piece_share, b.rings, stepped.stats.patches, b.linked_to_3_share, b.largest_piece_share);
  EXPECT_EQ(stepped.stats.filled_elements, 0);
  EXPECT_GT(filled.stats.filled_elements, a.rings / 2);
  EXPECT_LT(filled.stats.patches, stepped.stats.patches);
  EXPECT_NEAR(a.rings, b.rings, 0.02 * b.rings);
  EXPECT_GE(a.linked_to_3_share, b.linked_to_3_share - 0.03);
  EXPECT_GE(a.largest_piece_share, b.largest_piece_share - 0.08);
  EXPECT_EQ(filled.stats.intersecting_face_pairs, 0);
  EXPECT_LE(filled.stats.hole_area, stepped.stats.hole_area + 1e-4 * stepped.stats.covered_area);
}

INSTANTIATE_TEST_SUITE_P(Bases, FilledPattern, ::testing::Values("sphere.off", "fertility.off"),
                         [](const auto& info) { return std::string(info.param).substr(0, std::string(info.param).find('.')); });

// Over scanned bases whose layouts hold cones of negative index (saddles between the bunny's
// ears, fertility's handles), a window that wrapped over itself round one placed rings of one
// sheet over those of the other, and refused them as collisions. Rings
// filled straight from the layout up to half a period from a cone refuse a few more there, where
// the pattern breaks: 7% over the bunny.
class ScannedBaseLinks : public ::testing::TestWithParam<const char*> {};

TEST_P(ScannedBaseLinks, TheDefaultMailLinksAsOnAPlane) {
  const auto file = kShared / "data/meshes" / GetParam();
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const TriMesh swatch = default_swatch();
  const SurfaceRun run = run_surface(read_mesh(file), swatch, 0.14);
  const RingLinks links = links_of(run.output);
  const double radius = links.median_radius / (links_of(swatch).median_radius * run.unit);
  std::printf("%s 0.14: %d rings, linked to >= 3 %.3f, largest piece %.3f, radius / asked %.3f, rejected %d\n",
              GetParam(), links.rings, links.linked_to_3_share, links.largest_piece_share, radius,
              run.stats.merges.rejected_inputs);
  EXPECT_GE(links.linked_to_3_share, 0.85);
  EXPECT_GE(links.largest_piece_share, 0.95);
  EXPECT_LE(run.stats.merges.rejected_inputs, 0.08 * links.rings);
  EXPECT_EQ(run.stats.intersecting_face_pairs, 0);
  EXPECT_NEAR(radius, 1.0, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Bases, ScannedBaseLinks, ::testing::Values("bunny.off", "fertility.off"),
                         [](const auto& info) { return std::string(info.param).substr(0, std::string(info.param).find('.')); });

// Every change the step makes is tested in the space the output lives in, so where synthesis
// decides in that space (displacement along normals, or the original shell map) no two elements
// pass through each other before the clean-up pass: nothing is left for it to drop.
TEST(SurfaceQuilting, NoElementsIntersectWhereSynthesisDecidesInOutputSpace) {
  const TriMesh swatch = make_chainmail(ChainmailOptions::small());
  // Per-patch charts, whose seams misregister: on the shared layout the sphere's rings register
  // exactly, and no merge would need refusing.
  const auto per_patch = [](SurfaceQuiltOptions& options) { options.shared_layout = false; };
  for (const Embed embed : {Embed::normal, Embed::original_shell}) {
    const SurfaceRun run = run_surface(read_mesh(kSource / "data/sphere.off"), swatch, 0.3,
                                       engine::BackendChoice::cpu, 0, {}, embed, per_patch);
    SCOPED_TRACE(embed == Embed::normal ? "normal" : "original shell map");
    EXPECT_EQ(run.stats.intersecting_face_pairs, 0);
    EXPECT_EQ(run.stats.dropped_elements, 0);
    EXPECT_GT(run.stats.merges.refused_merges + run.stats.merges.undone_deformations, 0);
  }
}

TEST(SurfaceQuilting, HalvingTheScaleQuadruplesTheElements) {
  const TriMesh swatch = make_chainmail(ChainmailOptions::small());
  const TriMesh sphere = read_mesh(kSource / "data/sphere.off");
  // At coarser scales a larger share of rings is lost at patch edges, so the ratio runs above 4:
  // 5.14 (284 -> 1,461) with per-patch charts, 5.77 (599 -> 3,454) with the shared layout, which
  // keeps twice the rings at both scales but loses more of the coarse ones round its four cones.
  const SurfaceRun coarse = run_surface(sphere, swatch, 0.2);
  const SurfaceRun fine = run_surface(sphere, swatch, 0.1);
  int32_t coarse_elements = 0, fine_elements = 0;
  for (int32_t e : coarse.output.elements) coarse_elements = std::max(coarse_elements, e + 1);
  for (int32_t e : fine.output.elements) fine_elements = std::max(fine_elements, e + 1);
  const double ratio = static_cast<double>(fine_elements) / coarse_elements;
  std::printf("halving the scale: %d -> %d elements (%.2fx)\n", coarse_elements, fine_elements, ratio);
  EXPECT_GT(ratio, 3.5) << coarse_elements << " -> " << fine_elements;
  EXPECT_LT(ratio, 6.0) << coarse_elements << " -> " << fine_elements;
}

TEST(SurfaceQuilting, BackEndsAgree) {
  const TriMesh swatch = make_chainmail(ChainmailOptions::small());
  const TriMesh sphere = read_mesh(kSource / "data/sphere.off");
  {
    std::string why;
    const auto probe = test::open_backend(engine::Backend::vulkan, &why);
    MESHQUILT_REQUIRE_DEVICE(probe, why);
  }
  // Normal displacement and the original shell map: byte-identical.
  for (Embed embed : {Embed::normal, Embed::original_shell}) {
    const SurfaceRun cpu = run_surface(sphere, swatch, 0.3, engine::BackendChoice::cpu, 12, {}, embed);
    const SurfaceRun vulkan = run_surface(sphere, swatch, 0.3, engine::BackendChoice::vulkan, 12, {}, embed);
    EXPECT_EQ(cpu.output.positions, vulkan.output.positions);
    EXPECT_EQ(cpu.output.triangles, vulkan.output.triangles);
    EXPECT_EQ(cpu.output.sources, vulkan.output.sources);
  }
  // The stretch-minimized shell map: the same mesh (synthesis decides on the host-exact original
  // map), positions within float32 line-search rounding: 2e-3 of the shell height.
  const SurfaceRun cpu = run_surface(sphere, swatch, 0.3, engine::BackendChoice::cpu, 12);
  const SurfaceRun vulkan = run_surface(sphere, swatch, 0.3, engine::BackendChoice::vulkan, 12);
  EXPECT_EQ(cpu.output.triangles, vulkan.output.triangles);
  EXPECT_EQ(cpu.output.sources, vulkan.output.sources);
  ASSERT_EQ(cpu.output.positions.size(), vulkan.output.positions.size());
  for (size_t v = 0; v < cpu.output.positions.size(); ++v)
    EXPECT_NEAR(glm::distance(cpu.output.positions[v], vulkan.output.positions[v]), 0.0, 2e-3 * cpu.stats.shell_height);
}

// A patch that must shrink below the yarns' length to meet the distortion limit places none of
// them, and seeding the same cell again would fail alike: each retry allows twice the distortion.
// With a limit of 1.05 (every first patch on the sphere shrinks as far as it may) the retries
// at 2.1 and 4.2 leave 0.3% of the sphere in holes; without the rule, 2.2%. Per-patch charts:
// their distortion is the spread over the whole patch, which such a limit trips everywhere.
TEST(SurfaceQuilting, RetriesAllowMoreDistortionWhereAShrunkPatchPlacedNothing) {
  const TriMesh swatch = make_weave(WeaveOptions::small());
  const SurfaceRun run =
      run_surface(read_mesh(kSource / "data/sphere.off"), swatch, 0.3, engine::BackendChoice::cpu, 0, {}, Embed::shell,
                  [](SurfaceQuiltOptions& o) {
                    o.max_area_distortion = 1.05;
                    o.shared_layout = false;
                  });
  std::printf("sphere + weave, distortion limit 1.05: %d patches, %d shrunk, %d holes\n", run.stats.patches,
              run.stats.shrunk_patches, run.stats.holes);
  EXPECT_GT(run.stats.shrunk_patches, run.stats.patches / 3);
  expect_quality(run, swatch, "sphere + weave, distortion limit 1.05");
}

// A flat square whose triangles shrink geometrically from one side to the other: the widest are
// about 600 times wider than the narrowest (split into cells), the narrowest far below a cell.
TEST(SurfaceQuilting, StronglyNonUniformTriangles) {
  TriMesh base;
  const int columns = 10, rows = 8;
  const double ratio = 1.9;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i)
      base.positions.emplace_back((std::pow(ratio, i) - 1.0) / (std::pow(ratio, columns) - 1.0),
                                  static_cast<double>(j) / rows, 0.0);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int32_t a = j * (columns + 1) + i, b = a + 1, c = a + columns + 1, d = c + 1;
      base.triangles.push_back({a, b, d});
      base.triangles.push_back({a, d, c});
    }
  const TriMesh swatch = make_chainmail(ChainmailOptions::small());
  const SurfaceRun run = run_surface(base, swatch, 0.25);
  expect_quality(run, swatch, "non-uniform square");
  std::printf("non-uniform square: %d patches, %d cells, %d holes\n", run.stats.patches, run.stats.cells, run.stats.holes);
}

// Weft yarns (told from warps by the source element) run along the field: the mean unsigned angle
// between a weft's local direction (principal axis of its vertices within 1.5 yarn pitches) and the
// field at the nearest base vertex, both in that vertex's tangent plane, stays under 15 degrees.
TEST(SurfaceQuilting, WeftsFollowTheGuidanceField) {
  const auto file = kShared / "data/meshes/bunny.off";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const WeaveOptions weave = WeaveOptions::small();
  const TriMesh swatch = make_weave(weave);
  const int warps = weave_yarn_counts(weave).x;
  const double pitch = weave_period(weave).x / warps;
  const TriMesh raw = read_mesh(file);
  const TriMesh base = prepare_base(raw, "bunny");
  const std::vector<FieldConstraint> constraints = read_field_file(kSource / "data/bunny_field.json", base);
  ASSERT_EQ(constraints.size(), 6u);
  const SurfaceRun run = run_surface(raw, swatch, 0.16, engine::BackendChoice::cpu, 0, constraints);
  const BaseSurface surface(run.base);
  const GuidanceField field = interpolate_field(surface, constraints);

  const double radius = 1.5 * pitch * run.unit;
  double angle_sum = 0.0, calm_sum = 0.0;
  int samples = 0, calm = 0;
  // Weft vertices by output element.
  std::map<int32_t, std::vector<Vec3>> wefts;
  for (size_t f = 0; f < run.output.num_faces(); ++f) {
    if (run.output.sources[f] < warps) continue;
    for (int32_t v : run.output.triangles[f]) wefts[run.output.elements[f]].push_back(run.output.positions[v]);
  }
  for (const auto& [id, points] : wefts) {
    for (size_t i = 0; i < points.size(); i += 25) {
      const Vec3& p = points[i];
      // Principal axis of the nearby vertices (power iteration on their covariance).
      Vec3 mean(0.0);
      int count = 0;
      for (const Vec3& q : points)
        if (glm::distance(p, q) <= radius) {
          mean += q;
          ++count;
        }
      if (count < 12) continue;
      mean /= count;
      glm::dmat3 covariance(0.0);
      for (const Vec3& q : points)
        if (glm::distance(p, q) <= radius) covariance += glm::outerProduct(q - mean, q - mean);
      Vec3 axis(1.0, 0.3, 0.1);
      for (int k = 0; k < 60; ++k) axis = glm::normalize(covariance * axis);
      size_t nearest = 0;
      for (size_t v = 1; v < run.base.num_vertices(); ++v)
        if (glm::distance(run.base.positions[v], p) < glm::distance(run.base.positions[nearest], p)) nearest = v;
      const Vec3 n = surface.vertex_normals[nearest];
      const Vec3 tangent = axis - glm::dot(axis, n) * n;
      if (glm::length(tangent) < 0.5) continue;  // a yarn's cap or a crossing seen end on
      const double c = std::abs(glm::dot(glm::normalize(tangent), field.directions[nearest]));
      const double angle = std::acos(std::min(1.0, c));
      angle_sum += angle;
      ++samples;
      // Where the field itself turns by more than 45 degrees within the window, no straight
      // stretch of yarn can follow it (a singularity's neighbourhood).
      double turn = 0.0;
      for (size_t v = 0; v < run.base.num_vertices(); ++v)
        if (glm::distance(run.base.positions[v], p) < radius)
          turn = std::max(turn, std::acos(std::min(1.0, glm::dot(field.directions[v], field.directions[nearest]))));
      if (turn < M_PI / 4.0) {
        calm_sum += angle;
        ++calm;
      }
    }
  }
  ASSERT_GT(samples, 100);
  const double mean_degrees = angle_sum / samples * 180.0 / M_PI;
  const double calm_degrees = calm_sum / std::max(1, calm) * 180.0 / M_PI;
  std::printf("wefts against the field: mean unsigned angle %.1f degrees over %d samples, %.1f over the %d where "
              "the field turns less than 45 degrees\n", mean_degrees, samples, calm_degrees, calm);
  // Measured under the shell map, seeds 1-3: 9.9, 10.2 and 12.7 over all samples, 7.2-9.6 away
  // from singularities (when the field was solved in space rather than in the tangent planes:
  // 13.6-17.1). Near a singularity no straight stretch of yarn follows the field.
  EXPECT_LT(calm_degrees, 11.0) << calm << " samples";
  EXPECT_GT(calm, samples / 2);
  EXPECT_LT(mean_degrees, 15.0) << samples << " samples";
}

// Real bases from ../shared: a closed scan, genus 4, an open base, two components, the teapot.
struct SharedCase {
  const char* file;
  double scale;
  QualityBar bar;
  Embed embed = Embed::shell;
  bool weave = false;  // the small plain weave instead of the small chain mail
};

class SharedBase : public ::testing::TestWithParam<SharedCase> {};

TEST_P(SharedBase, MeetsTheQualityBar) {
  const auto file = kShared / "data/meshes" / GetParam().file;
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const TriMesh swatch =
      GetParam().weave ? make_weave(WeaveOptions::small()) : make_chainmail(ChainmailOptions::small());
  const SurfaceRun run =
      run_surface(read_mesh(file), swatch, GetParam().scale, engine::BackendChoice::cpu, 0, {}, GetParam().embed);
  expect_quality(run, swatch, GetParam().file, GetParam().bar);
}

// Measured bounds where deformed elements pass through themselves (dropped, see decision 0033):
// fertility 4.0% of its rings (its coverage falls to 0.936 with them), the two knots 3.8%, the
// teapot 12.9% (its crease rings fold with per-patch charts too: 30 of 187), the fertility weave
// 11.5% of its yarns, the bunny weave 3.0% (5 yarns, as many as before its yarns were placed on
// the weave's periods, now of fewer and longer pieces).
QualityBar folding_bar(QualityBar bar, double max_folded_share, double min_coverage = 0.97) {
  bar.max_folded_share = max_folded_share;
  bar.min_coverage = min_coverage;
  return bar;
}

// The teapot meets the bar through the shell map; under normal displacement its open rim and
// handle put some vertices on the far side of the nearest base sheet (signed height -0.033).
// Its rings, on the swatch's lattice, leave a little more of the rim and spout bare than rings
// placed at any phase did (coverage 0.970 against 0.978, with a third of the rejected inputs).
// The weave is the issue's other swatch; its footprint is square, so it needs a finer scale than
// the chain mail for 50 copies of it (55 at 0.13; 36 at 0.16).
INSTANTIATE_TEST_SUITE_P(Meshes, SharedBase,
                         ::testing::Values(SharedCase{"bunny.off", 0.16, issue_bar()},
                                           SharedCase{"fertility.off", 0.16, folding_bar(issue_bar(), 0.05, 0.93)},
                                           SharedCase{"head.off", 0.2, {}},
                                           SharedCase{"knot2.off", 0.2, folding_bar({}, 0.05)},
                                           SharedCase{"teapot.obj", 0.2, folding_bar({}, 0.15, 0.96)},
                                           SharedCase{"bunny.off", 0.13, folding_bar(issue_bar(), 0.04), Embed::shell, true},
                                           SharedCase{"fertility.off", 0.13, folding_bar(issue_bar(), 0.13), Embed::shell, true}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           return name.substr(0, name.find('.')) + (info.param.weave ? "_weave" : "_chainmail");
                         });

}  // namespace
}  // namespace meshquilt
