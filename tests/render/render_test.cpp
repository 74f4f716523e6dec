// Preview rendering: FaceBvh::ray_cast against a brute-force loop, framing against its closed
// form, one flat colour per visible element, PNG bytes read back by libpng, and the
// `meshquilt render` command's errors (one line, documented exit code, nothing written).
#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <random>
#include <set>
#include <string>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "render/camera_framing.h"
#include "render/element_palette.h"
#include "render/png_encoding.h"
#include "render/render_mesh.h"
#include "spatial/face_bvh.h"
#include "support/bumpy_sphere.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

// Closed axis-aligned box [lo, hi], 12 outward triangles, appended to `mesh` with element `id`.
void add_box(TriMesh& mesh, const Vec3& lo, const Vec3& hi, int32_t id) {
  const auto base = static_cast<int32_t>(mesh.positions.size());
  for (int c = 0; c < 8; ++c)
    mesh.positions.emplace_back((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({base + q[0], base + q[1], base + q[2]});
    mesh.triangles.push_back({base + q[0], base + q[2], base + q[3]});
    mesh.elements.push_back(id);
    mesh.elements.push_back(id);
  }
}

// Rectangle [0, a] x [0, b] at z = 0, two triangles.
TriMesh rectangle(double a, double b) {
  TriMesh mesh;
  mesh.positions = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

struct Coverage {
  long pixels = 0;
  int min_x = 1 << 30, max_x = -1, min_y = 1 << 30, max_y = -1;
};

Coverage coverage(const RgbImage& image, const Rgb8& background) {
  Coverage c;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (image.pixel(x, y) == background) continue;
      ++c.pixels;
      c.min_x = std::min(c.min_x, x);
      c.max_x = std::max(c.max_x, x);
      c.min_y = std::min(c.min_y, y);
      c.max_y = std::max(c.max_y, y);
    }
  return c;
}

std::set<Rgb8> foreground_colors(const RgbImage& image, const Rgb8& background) {
  std::set<Rgb8> colors;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.pixel(x, y) != background) colors.insert(image.pixel(x, y));
  return colors;
}

TEST(RayCast, MatchesBruteForceOnBumpySphere) {
  const TriMesh mesh = test::bumpy_sphere(24, 32, 1.0, Vec3(0.2, -0.1, 0.3), 5);
  const FaceBvh bvh(mesh);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 origin = Vec3(u(rng), u(rng), u(rng)) * (i % 2 ? 3.0 : 0.5);  // outside and inside
    Vec3 direction(u(rng), u(rng), u(rng));
    if (glm::length(direction) < 1e-3) continue;
    const double max_distance = i % 3 == 0 ? 2.5 : std::numeric_limits<double>::infinity();
    RayHit expected;
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      const Tri& t = mesh.triangles[f];
      const double d =
          ray_triangle(origin, direction, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
      if (d <= max_distance && d < expected.distance) expected = {static_cast<int32_t>(f), d};
    }
    const RayHit got = bvh.ray_cast(origin, direction, max_distance);
    ASSERT_EQ(got.face, expected.face) << "ray " << i;
    ASSERT_EQ(got.distance, expected.distance) << "ray " << i;
    hits += got.face >= 0;
  }
  EXPECT_GT(hits, 1000);  // most rays meet the sphere, some miss it
  EXPECT_LT(hits, 2000);
}

TEST(RayCast, TriangleHitDistanceAndMisses) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_DOUBLE_EQ(ray_triangle({0.5, 0.5, 3}, {0, 0, -2}, a, b, c), 1.5);    // t in units of |direction|
  EXPECT_DOUBLE_EQ(ray_triangle({0.5, 0.5, -3}, {0, 0, 1}, a, b, c), 3.0);    // seen from behind
  EXPECT_TRUE(std::isinf(ray_triangle({0.5, 0.5, 3}, {0, 0, 1}, a, b, c)));   // pointing away
  EXPECT_TRUE(std::isinf(ray_triangle({1.5, 1.5, 3}, {0, 0, -1}, a, b, c)));  // past the hypotenuse
  EXPECT_TRUE(std::isinf(ray_triangle({-1, 0.5, 0}, {1, 0, 0}, a, b, c)));    // in the plane
}

// An a x b rectangle seen from the top fills a/s x b/s pixels, with the pixel size s from the
// framing rule: s = max(a / (W (1 - 2m)), b / (H (1 - 2m))).
struct ShareCase {
  double a, b;
  int width, height;
};

void PrintTo(const ShareCase& p, std::ostream* out) {
  *out << p.a << " x " << p.b << " in " << p.width << " x " << p.height << " pixels";
}

class TopViewShare : public ::testing::TestWithParam<ShareCase> {};

TEST_P(TopViewShare, RectangleFillsClosedFormShare) {
  const ShareCase p = GetParam();
  RenderOptions options;
  options.width = p.width;
  options.height = p.height;
  options.view = View::top;
  options.samples = 1;
  const RgbImage image = render_mesh(rectangle(p.a, p.b), options);
  const double usable = 1.0 - 2.0 * options.margin;
  const double s = std::max(p.a / (p.width * usable), p.b / (p.height * usable));
  const double columns = p.a / s, rows = p.b / s;
  const Coverage c = coverage(image, options.background);
  // Edges fall on pixel boundaries or between centres: at most one row or column off per side.
  EXPECT_NEAR(c.pixels, columns * rows, columns + rows + 2)
      << "share " << double(c.pixels) / (p.width * p.height);
  EXPECT_NEAR(c.max_x - c.min_x + 1, columns, 1.0);
  EXPECT_NEAR(c.max_y - c.min_y + 1, rows, 1.0);
  // Centred, +x to the right and +y up: the rectangle's corner (0, 0) is bottom left, so a
  // half-covered L-shape would show up as an off-centre box.
  EXPECT_NEAR(0.5 * (c.min_x + c.max_x + 1), 0.5 * p.width, 1.0);
  EXPECT_NEAR(0.5 * (c.min_y + c.max_y + 1), 0.5 * p.height, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Framing, TopViewShare,
                         ::testing::Values(ShareCase{1, 1, 400, 300},        // 270 x 270 of 400 x 300
                                           ShareCase{1, 1, 300, 400},        // portrait
                                           ShareCase{2, 1, 400, 300},        // width-bound: 360 x 180
                                           ShareCase{1, 3, 400, 300},        // height-bound: 90 x 270
                                           ShareCase{0.01, 0.01, 64, 48}));  // scale does not matter

TEST(TopViewShare, UnitSquareInDefaultImage) {
  // The default 1024 x 768 image with 5% margins shows a unit square as 691.2 pixels, 60.8% of the
  // image.
  RenderOptions options;
  options.view = View::top;
  options.samples = 1;
  const Coverage c = coverage(render_mesh(rectangle(1, 1), options), options.background);
  EXPECT_NEAR(double(c.pixels) / (1024.0 * 768.0), 691.2 * 691.2 / (1024.0 * 768.0), 0.003);
}

TEST(Framing, EveryViewFitsTheBoxTightlyInsideTheMargins) {
  TriMesh mesh;
  add_box(mesh, {0, 0, 0}, {2, 1, 0.5}, 0);
  for (View view : {View::top, View::oblique, View::front, View::side}) {
    RenderOptions options;
    options.width = 320;
    options.height = 240;
    options.view = view;
    options.samples = 1;
    const Coverage c = coverage(render_mesh(mesh, options), options.background);
    const double mx = options.margin * options.width, my = options.margin * options.height;
    EXPECT_GE(c.min_x, mx - 1);
    EXPECT_LE(c.max_x + 1, options.width - mx + 1);
    EXPECT_GE(c.min_y, my - 1);
    EXPECT_LE(c.max_y + 1, options.height - my + 1);
    // Tight in at least one direction: the box touches both margins there.
    const bool tight_x = c.min_x <= mx + 1 && c.max_x + 1 >= options.width - mx - 1;
    const bool tight_y = c.min_y <= my + 1 && c.max_y + 1 >= options.height - my - 1;
    EXPECT_TRUE(tight_x || tight_y) << "view " << static_cast<int>(view);
  }
}

TEST(Framing, FrontAndSideShowTheExpectedFaces) {
  // Box 2 wide (x), 1 deep (y), 0.5 high (z). Front (along +y) shows 2 x 0.5; side (along -x)
  // shows 1 x 0.5: the projected aspect tells which axes the view uses.
  TriMesh mesh;
  add_box(mesh, {0, 0, 0}, {2, 1, 0.5}, 0);
  RenderOptions options;
  options.width = 400;
  options.height = 400;
  options.samples = 1;
  options.view = View::front;
  Coverage c = coverage(render_mesh(mesh, options), options.background);
  EXPECT_NEAR(double(c.max_x - c.min_x + 1) / (c.max_y - c.min_y + 1), 4.0, 0.1);
  options.view = View::side;
  c = coverage(render_mesh(mesh, options), options.background);
  EXPECT_NEAR(double(c.max_x - c.min_x + 1) / (c.max_y - c.min_y + 1), 2.0, 0.05);
}

TEST(Framing, UpShowsTheGivenAxisUpward) {
  // From the front a box shows its x extent across and its up axis's extent upward: 0.5 x 2
  // with y up (z, 1 deep, turned to face the camera), 0.5 x 1 with z up.
  TriMesh mesh;
  add_box(mesh, {0, 0, 0}, {0.5, 2, 1}, 0);
  RenderOptions options;
  options.width = options.height = 400;
  options.samples = 1;
  options.view = View::front;
  const auto aspect = [&](const TriMesh& m) {
    const Coverage c = coverage(render_mesh(m, options), options.background);
    return double(c.max_x - c.min_x + 1) / (c.max_y - c.min_y + 1);
  };
  EXPECT_NEAR(aspect(mesh), 0.5, 0.02);
  options.up = 1;
  EXPECT_NEAR(aspect(mesh), 0.25, 0.01);
  // x up: the box's y extent shows across, its x extent upward.
  TriMesh lying;
  add_box(lying, {0, 0, 0}, {2, 0.5, 1}, 0);
  options.up = 0;
  EXPECT_NEAR(aspect(lying), 0.25, 0.01);
  options.up = 3;
  EXPECT_THROW(render_mesh(mesh, options), InputError);
}

TEST(Framing, ObliqueViewLooksDownAt35Degrees) {
  const Vec3 d = view_direction(View::oblique);
  EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
  EXPECT_NEAR(std::asin(-d.z) * 180.0 / M_PI, kObliqueElevationDegrees, 1e-9);
  EXPECT_NEAR(std::abs(d.x), std::abs(d.y), 1e-12);  // a diagonal azimuth
  const OrthographicCamera camera = frame_box({0, 0, 0}, {1, 1, 1}, View::oblique, 100, 100, 0.05);
  EXPECT_GT(camera.up.z, 0.0);  // +z shows upward in the image
  EXPECT_NEAR(glm::dot(glm::cross(camera.right, camera.up), -camera.forward), 1.0, 1e-12);
}

// Three separated boxes seen from the top, plus a fourth hidden under the first: each visible
// element shows as exactly one colour (their tops face the camera, so shading is uniform).
TriMesh three_boxes_and_a_hidden_one(const std::vector<int32_t>& ids) {
  TriMesh mesh;
  add_box(mesh, {0, 0, 1}, {1, 1, 2}, ids[0]);
  add_box(mesh, {2, 0, 0}, {3, 1, 1}, ids[1]);
  add_box(mesh, {0.5, 2, 0}, {2.5, 3, 0.5}, ids[2]);
  add_box(mesh, {0.1, 0.1, 0}, {0.9, 0.9, 0.5}, ids[3]);  // under the first box
  return mesh;
}

RgbImage render_top_elements(const TriMesh& mesh) {
  RenderOptions options;
  options.width = 200;
  options.height = 160;
  options.view = View::top;
  options.mode = RenderMode::elements;
  options.samples = 1;
  return render_mesh(mesh, options);
}

TEST(ElementsMode, OneColourPerVisibleElement) {
  const TriMesh mesh = three_boxes_and_a_hidden_one({7, 2, 40, 3});
  const RgbImage image = render_top_elements(mesh);
  const std::set<Rgb8> colors = foreground_colors(image, RenderOptions{}.background);
  EXPECT_EQ(colors.size(), 3u);
  // The centre pixel of each box top shows that box's colour, and the three differ.
  auto at = [&](double x, double y) {
    const OrthographicCamera camera = frame_box({0, 0, 0}, {3, 3, 2}, View::top, 200, 160, 0.05);
    const Vec3 offset = Vec3(x, y, 0) - camera.center;
    return image.pixel(static_cast<int>(0.5 * 200 + glm::dot(offset, camera.right) / camera.pixel_size),
                       static_cast<int>(0.5 * 160 - glm::dot(offset, camera.up) / camera.pixel_size));
  };
  const std::set<Rgb8> centres = {at(0.5, 0.5), at(2.5, 0.5), at(1.5, 2.5)};
  EXPECT_EQ(centres, colors);
}

TEST(ElementsMode, SharedIdsShareAColour) {
  // Elements come from the mesh's ids, not its connected pieces: boxes 1 and 2 share an id.
  const TriMesh mesh = three_boxes_and_a_hidden_one({5, 5, 6, 8});
  EXPECT_EQ(foreground_colors(render_top_elements(mesh), RenderOptions{}.background).size(), 2u);
}

TEST(ElementsMode, WithoutIdsConnectedComponentsAreElements) {
  TriMesh mesh = three_boxes_and_a_hidden_one({0, 0, 0, 0});
  mesh.elements.clear();
  EXPECT_EQ(foreground_colors(render_top_elements(mesh), RenderOptions{}.background).size(), 3u);
  EXPECT_EQ(face_element_ids(mesh), (std::vector<int32_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,  //
                                                          1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,  //
                                                          2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2,  //
                                                          3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3}));
}

TEST(ElementsMode, PaletteIsSpreadAndDeterministic) {
  constexpr int kIds = 64;
  double closest = 1e9, closest_neighbours = 1e9;
  for (int i = 0; i < kIds; ++i) {
    EXPECT_EQ(element_color(i), element_color(i));
    const Vec3 c = element_color(i);
    EXPECT_GE(std::max(c.r, std::max(c.g, c.b)), 0.79);  // light enough to read shape on
    for (int j = i + 1; j < kIds; ++j) closest = std::min(closest, glm::length(c - element_color(j)));
    if (i > 0) closest_neighbours = std::min(closest_neighbours, glm::length(c - element_color(i - 1)));
  }
  EXPECT_GT(closest, 0.03);                 // no two of 64 ids look the same
  EXPECT_GT(closest_neighbours, 0.3);       // consecutive ids are far apart
  const Vec3 negative = element_color(-1);  // a foreign label: a colour, not a crash
  EXPECT_TRUE(std::isfinite(negative.r));
}

TEST(CloseUp, KeepsWholeElementsWithAVertexWithinTheRadius) {
  TriMesh mesh;
  add_box(mesh, {0, 0, 0}, {1, 1, 1}, 3);
  add_box(mesh, {4, 0, 0}, {5, 1, 1}, 9);
  add_box(mesh, {8, 0, 0}, {9, 1, 1}, 4);
  // (5.5, 0.5, 0.5): the middle box's corners lie sqrt(0.75) away, the last box's sqrt(6.5).
  const TriMesh near = close_up_elements(mesh, {{5.5, 0.5, 0.5}, 1.0});
  EXPECT_EQ(near.num_faces(), 12u);
  for (int32_t id : near.elements) EXPECT_EQ(id, 9);
  EXPECT_EQ(close_up_elements(mesh, {{5.5, 0.5, 0.5}, 2.6}).num_faces(), 24u);
  EXPECT_THROW(close_up_elements(mesh, {{5.5, 0.5, 0.5}, 0.8}), InputError);
}

TEST(CloseUp, LooksAtThePointFromOutside) {
  // A row of boxes along x; the last one's +x faces (id 7) face away from the row's centre, its
  // other faces are id 8. Seen from outside along -x, only id 7 shows.
  TriMesh mesh;
  add_box(mesh, {0, 0, 0}, {1, 1, 1}, 1);
  add_box(mesh, {4, 0, 0}, {5, 1, 1}, 8);
  for (size_t f = 12; f < mesh.num_faces(); ++f) {
    bool on_plus_x = true;
    for (int32_t v : mesh.triangles[f]) on_plus_x = on_plus_x && mesh.positions[v].x == 5.0;
    if (on_plus_x) mesh.elements[f] = 7;
  }
  RenderOptions options;
  options.width = 120;
  options.height = 90;
  options.mode = RenderMode::elements;
  options.samples = 1;
  options.close_up = CloseUp{{5.2, 0.5, 0.5}, 1.5};
  const std::set<Rgb8> colors = foreground_colors(render_mesh(mesh, options), options.background);
  ASSERT_EQ(colors.size(), 1u);
  // The face's colour at the headlight's full strength differs from element 8's and element 1's.
  options.close_up->point = Vec3(-0.2, 0.5, 0.5);  // now from -x: box 1's -x face
  const std::set<Rgb8> other = foreground_colors(render_mesh(mesh, options), options.background);
  ASSERT_EQ(other.size(), 1u);
  EXPECT_NE(*colors.begin(), *other.begin());
  // The same picture as the -x face of box 1 alone, coloured as id 1.
  TriMesh alone;
  add_box(alone, {0, 0, 0}, {1, 1, 1}, 1);
  EXPECT_EQ(render_mesh(alone, options).rgb, render_mesh(mesh, options).rgb);
}

TEST(ShadedMode, FacesAreTwoSidedAndLitByTheirSlope) {
  RenderOptions options;
  options.width = 64;
  options.height = 48;
  options.view = View::top;
  options.samples = 1;
  TriMesh up = rectangle(1, 1);
  TriMesh down = up;
  for (Tri& t : down.triangles) std::swap(t[1], t[2]);
  const RgbImage a = render_mesh(up, options), b = render_mesh(down, options);
  EXPECT_EQ(a.rgb, b.rgb);
  // A square tilted away from the viewer by 60 degrees gets less of the headlight: darker.
  TriMesh tilted = up;
  for (Vec3& p : tilted.positions) p = Vec3(p.x, 0.5 * p.y, std::sqrt(3.0) / 2.0 * p.y);
  const RgbImage t = render_mesh(tilted, options);
  const Rgb8 flat = a.pixel(32, 24), slope = t.pixel(32, 24);
  EXPECT_NE(slope, options.background);
  EXPECT_LT(int(slope[0]) + slope[1] + slope[2], int(flat[0]) + flat[1] + flat[2]);
}

TEST(RenderOptionsCheck, RefusesAbsurdSizesAndEmptyMeshes) {
  RenderOptions options;
  options.width = 8193;
  try {
    render_mesh(rectangle(1, 1), options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_option);
    EXPECT_NE(e.text().find("{size}"), std::string::npos);
  }
  options.width = 8192;
  options.height = 0;
  EXPECT_THROW(validate_render_options(options), InputError);
  options.height = 8192;
  EXPECT_NO_THROW(validate_render_options(options));
  try {
    render_mesh(TriMesh{}, RenderOptions{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_mesh);
  }
}

TEST(PngEncoding, LibpngReadsBackTheSamePixels) {
  RgbImage image;
  image.width = 37;
  image.height = 11;
  for (int i = 0; i < image.width * image.height * 3; ++i)
    image.rgb.push_back(static_cast<uint8_t>(i * 7 + 3));
  const std::string bytes = encode_png(image);
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()));
  EXPECT_EQ(png.width, 37u);
  EXPECT_EQ(png.height, 11u);
  png.format = PNG_FORMAT_RGB;
  std::vector<uint8_t> pixels(PNG_IMAGE_SIZE(png));
  ASSERT_TRUE(png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr));
  EXPECT_EQ(pixels, image.rgb);
}

// `meshquilt render`: errors are one line naming the file or option with the documented exit
// code, and neither a new output nor a change to an existing one.
class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratch_dir(std::string("render_") +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TriMesh mesh;
    add_box(mesh, {0, 0, 0}, {1, 1, 0.3}, 0);
    add_box(mesh, {1.5, 0, 0}, {2.5, 1, 0.3}, 1);
    good_ = dir_ / "boxes.ply";
    write_mesh(mesh, good_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void expect_failure(const std::string& args, const fs::path& output, int code, const std::string& needle) {
    const bool existed = fs::exists(output);
    const std::string before = existed ? test::read_file(output) : "";
    const test::CliResult r = test::run_cli("render " + args + " -o '" + output.string() + "'");
    EXPECT_EQ(r.exit_code, code) << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(fs::exists(output), existed);
    if (existed) {
      EXPECT_EQ(test::read_file(output), before);
    }
    for (const auto& entry : fs::directory_iterator(dir_))
      EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "left behind: " << entry.path();
  }
  fs::path dir_, good_;
};

TEST_F(RenderCli, MissingFile) {
  expect_failure("'" + (dir_ / "nope.ply").string() + "'", dir_ / "out.png", 3, "nope.ply");
}

TEST_F(RenderCli, UnreadableFormat) {
  test::write_file(dir_ / "mesh.xyz", "1 2 3\n");
  expect_failure("'" + (dir_ / "mesh.xyz").string() + "'", dir_ / "out.png", 4, "mesh.xyz");
}

TEST_F(RenderCli, EmptyMesh) {
  test::write_file(dir_ / "empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  expect_failure("'" + (dir_ / "empty.off").string() + "'", dir_ / "out.png", 5, "empty.off");
}

TEST_F(RenderCli, ExistingOutputLeftUntouched) {
  test::write_file(dir_ / "out.png", "previous picture");
  test::write_file(dir_ / "empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  expect_failure("'" + (dir_ / "empty.off").string() + "'", dir_ / "out.png", 5, "empty.off");
  expect_failure("'" + (dir_ / "nope.ply").string() + "'", dir_ / "out.png", 3, "nope.ply");
  expect_failure("'" + good_.string() + "' --size 9000x768", dir_ / "out.png", 6, "--size");
}

TEST_F(RenderCli, BadOptions) {
  const std::string mesh = "'" + good_.string() + "'";
  expect_failure(mesh + " --size 8193x10", dir_ / "out.png", 6, "--size");
  expect_failure(mesh + " --size 0x10", dir_ / "out.png", 6, "--size");
  expect_failure(mesh + " --size 640by480", dir_ / "out.png", 6, "--size");
  expect_failure(mesh + " --view below", dir_ / "out.png", 6, "--view");
  expect_failure(mesh + " --mode wireframe", dir_ / "out.png", 6, "--mode");
  expect_failure(mesh + " --up w", dir_ / "out.png", 6, "--up");
  expect_failure(mesh + " --around 1,2", dir_ / "out.png", 6, "--around");
  expect_failure(mesh + " --around 1,2,x", dir_ / "out.png", 6, "--around");
  expect_failure(mesh + " --radius 0.5", dir_ / "out.png", 6, "--radius");
  expect_failure(mesh + " --around 1,0.5,0.3 --radius -1", dir_ / "out.png", 6, "--radius");
  expect_failure(mesh + " --around 50,50,50 --radius 0.5", dir_ / "out.png", 5, "boxes.ply");
  expect_failure(mesh, dir_ / "out.jpg", 4, "out.jpg");
  expect_failure(mesh, dir_ / "missing" / "out.png", 7, "out.png");
}

TEST_F(RenderCli, WritesACloseUp) {
  const fs::path output = dir_ / "near.png";
  const test::CliResult r = test::run_cli("render '" + good_.string() + "' --around 2.6,0.5,0.15 --radius 0.6 --size 64x48 -o '" +
                                          output.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(output));
}

TEST_F(RenderCli, WritesAPngOfTheRequestedSize) {
  const fs::path output = dir_ / "boxes.png";
  test::write_file(output, "previous picture");  // replaced on success
  const test::CliResult r = test::run_cli("render '" + good_.string() +
                                          "' --size 120x90 --mode elements -o '" + output.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string bytes = test::read_file(output);
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()));
  EXPECT_EQ(png.width, 120u);
  EXPECT_EQ(png.height, 90u);
  png_image_free(&png);
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "left behind: " << entry.path();
}

}  // namespace
}  // namespace meshquilt
