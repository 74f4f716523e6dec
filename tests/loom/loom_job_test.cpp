#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "jobs/loom_job.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "spatial/intersecting_pairs.h"
#include "swatch/weave.h"

namespace meshquilt {
namespace {

ColourImage image(int width, int height, const std::function<glm::dvec3(int, int)>& colour) {
  ColourImage out;
  out.width = width;
  out.height = height;
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) out.rgb.push_back(colour(c, r));
  return out;
}

TEST(LoomJob, DesignColoursNameTheirWeaves) {
  // Left half red, right half blue: plain and twill 2/2.
  const ColourImage posterized =
      image(12, 9, [](int c, int) { return c < 6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1); });
  const std::vector<ColourWeave> weaves = parse_colour_weaves("FF0000=plain,0000ff=twill:2/2");
  const LoomDesign d = design_of(posterized, weaves, "p.png");
  const WeavePattern plain = twill_pattern(1, 1), twill = twill_pattern(2, 2);
  for (int r = 0; r < d.rows; ++r)
    for (int c = 0; c < d.columns; ++c) EXPECT_EQ(d.at(r, c), (c < 6 ? plain : twill).over(c, -r)) << r << ", " << c;
  // A colour without a weave is refused by pixel.
  const ColourImage stray = image(3, 3, [](int c, int r) { return c == 2 && r == 1 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0); });
  try {
    design_of(stray, weaves, "p.png");
    FAIL() << "a green pixel took a weave";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("p.png: pixel (2, 1) is 00FF00"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_colour_weaves("FF0000"), InputError);
  EXPECT_THROW(parse_colour_weaves("FF0000=tweed"), InputError);
}

TEST(LoomJob, YarnColoursFollowTheirMapsWholeOrStreamed) {
  WeaveOptions o;
  o.warps = o.wefts = 6;
  LoomRequest request;
  request.design = image(5, 4, [](int c, int r) { return (c + r) % 2 ? glm::dvec3(1.0) : glm::dvec3(0.0); });
  request.exemplars = {make_weave(o)};
  request.exemplar_names = {"plain"};
  request.stations = 4;
  request.sides = 5;
  request.warp_types = image(2, 1, [](int c, int) { return c ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0); });
  request.weft_types = image(1, 3, [](int, int r) { return glm::dvec3(0, 0, r / 2.0); });
  check_loom_request(request);
  const LoomOutcome whole = run_loom(request);
  const TriMesh& mesh = whole.fabric.mesh;
  ASSERT_EQ(mesh.colors.size(), mesh.num_vertices());
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const int e = mesh.elements[f];
    const std::array<uint8_t, 3> want =
        e < 5 ? (e % 2 ? std::array<uint8_t, 3>{255, 0, 0} : std::array<uint8_t, 3>{0, 255, 0})
              : std::array<uint8_t, 3>{0, 0, static_cast<uint8_t>(std::lround(255.0 * ((e - 5) % 3) / 2.0))};
    EXPECT_EQ(mesh.colors[mesh.triangles[f][0]], want) << "yarn " << e;
  }
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "meshquilt_loom_job";
  std::filesystem::create_directories(folder);
  write_mesh(mesh, folder / "whole.ply");
  request.ply_output = folder / "streamed.ply";
  run_loom(request);
  const auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(folder / "streamed.ply"), bytes(folder / "whole.ply"));
  std::filesystem::remove_all(folder);
}

// An exemplar exported as a triangle soup (every face its own corners), y up as Blender writes
// OBJ, is welded and turned on reading and weaves the fabric its welded self does.
TEST(LoomJob, AnExemplarAsATriangleSoupWeavesAsItsWeldedSelf) {
  WeaveOptions o;
  o.pattern = twill_pattern(2, 2);
  o.warps = o.wefts = 8;
  const TriMesh welded = make_weave(o);
  TriMesh soup;
  for (const Tri& t : welded.triangles) {
    const int32_t first = static_cast<int32_t>(soup.positions.size());
    for (int32_t v : t) {
      const Vec3& p = welded.positions[v];
      soup.positions.push_back(Vec3(p.y, p.z, p.x));  // x, y, z to z, x, y: z up becomes y up
    }
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  LoomRequest request;
  request.design = image(9, 7, [](int c, int r) { return (c + r) % 4 < 2 ? glm::dvec3(0.0) : glm::dvec3(1.0); });
  request.exemplar_names = {"soup.stl"};
  request.stations = 4;
  request.sides = 5;
  request.exemplars = {soup};
  const LoomOutcome from_soup = run_loom(request);
  EXPECT_GT(from_soup.stats["loom"]["exemplars"][0]["repairs"]["welded_vertices"].get<int64_t>(), 0);
  request.exemplars = {welded};
  const LoomOutcome from_welded = run_loom(request);
  ASSERT_EQ(from_soup.fabric.mesh.num_vertices(), from_welded.fabric.mesh.num_vertices());
  ASSERT_EQ(from_soup.fabric.mesh.triangles, from_welded.fabric.mesh.triangles);
  for (size_t v = 0; v < from_soup.fabric.mesh.num_vertices(); ++v)
    EXPECT_LT(glm::length(from_soup.fabric.mesh.positions[v] - from_welded.fabric.mesh.positions[v]), 1e-9);
}

// A hemisphere of radius 1 (a disc), made here by rings of latitude.
TriMesh hemisphere(int rings, int segments, bool closed) {
  TriMesh m;
  m.positions.push_back(Vec3(0, 0, 1));
  const int last = closed ? 2 * rings - 1 : rings;
  for (int i = 1; i <= last; ++i) {
    const double polar = 0.5 * 3.14159265358979 * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double a = 2.0 * 3.14159265358979 * j / segments;
      m.positions.push_back(Vec3(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar)));
    }
  }
  const auto at = [segments](int ring, int j) { return 1 + (ring - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) m.triangles.push_back({0, at(1, j), at(1, j + 1)});
  for (int i = 1; i < last; ++i)
    for (int j = 0; j < segments; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  if (closed) {
    m.positions.push_back(Vec3(0, 0, -1));
    const int south = static_cast<int>(m.positions.size()) - 1;
    for (int j = 0; j < segments; ++j) m.triangles.push_back({south, at(last, j + 1), at(last, j)});
  }
  return m;
}

TEST(LoomJob, AFabricDrapesOverADiscAndNotOverASphere) {
  WeaveOptions o;
  o.warps = o.wefts = 6;
  LoomRequest request;
  request.design = image(16, 16, [](int c, int r) { return (c + r) % 2 ? glm::dvec3(1.0) : glm::dvec3(0.0); });
  request.exemplars = {make_weave(o)};
  request.exemplar_names = {"plain"};
  request.stations = 6;
  request.sides = 6;
  request.base = hemisphere(12, 32, false);
  request.scale = 0.6;
  check_loom_request(request);
  const LoomOutcome draped = run_loom(request);
  const TriMesh& mesh = draped.fabric.mesh;
  EXPECT_TRUE(inspect_surface(mesh).closed_manifold());
  EXPECT_EQ(draped.stats["loom"]["drape"]["yarn_pieces"].get<int>(), 32);  // every yarn lands whole
  EXPECT_TRUE(intersecting_face_pairs(mesh, mesh.elements, IntersectionScope::different_elements).empty());
  // On the hemisphere, just above it: no deeper than the base's facets lie inside the sphere
  // (1 - cos of half the largest angle between rings, 0.0048), no higher than the fabric's
  // thickness (crimp and yarns) at its scale.
  const double per_pitch = draped.stats["loom"]["drape"]["base_units_per_pitch"].get<double>();
  double low = 1e300, high = -1e300;
  for (const Vec3& p : mesh.positions) {
    low = std::min(low, glm::length(p) - 1.0);
    high = std::max(high, glm::length(p) - 1.0);
  }
  EXPECT_GT(low, -0.0049);
  EXPECT_LT(high, 1.5 * per_pitch);
  request.base = hemisphere(12, 32, true);
  try {
    run_loom(request);
    FAIL() << "a fabric draped over a closed sphere";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("drapes over a disc"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshquilt
