// `meshquilt animate` and `swatch vine --frames` end to end: a still swatch leaves the result as it
// was, the shipped vine sways by at least a quarter of its height with every element closed and
// apart in every frame, a curved result sways along the surface (checked against the sphere's own
// normals), and over a moving base the two motions add.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>

#include "inspect/element_topology.h"
#include "mesh/mesh_io.h"
#include "spatial/intersecting_pairs.h"
#include "support/run_cli.h"

namespace meshquilt::test {
namespace {

namespace fs = std::filesystem;

class Animate : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch_dir("animate_cli"));
    ASSERT_EQ(run_cli("swatch vine --frames 8 -o " + at("vine.ply")).exit_code, 0);
    const CliResult plane = run_cli("synth --progress none --backend cpu --plane 2x2 --swatch " +
                                    at("vine.ply") + " --provenance -o " + at("plane.ply"));
    ASSERT_EQ(plane.exit_code, 0) << plane.output;
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string at(const std::string& name) { return "'" + (*dir_ / name).string() + "'"; }
  static fs::path* dir_;
};
fs::path* Animate::dir_ = nullptr;

TEST_F(Animate, AStillSwatchLeavesTheResultAsItWas) {
  fs::create_directories(*dir_ / "still");
  fs::copy_file(*dir_ / "vine.ply", *dir_ / "still" / "a.ply", fs::copy_options::overwrite_existing);
  fs::copy_file(*dir_ / "vine.ply", *dir_ / "still" / "b.ply", fs::copy_options::overwrite_existing);
  const CliResult r = run_cli("animate --quilt " + at("plane.ply") + " --swatch-frames " + at("still") +
                              " -o " + at("still_out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_file(*dir_ / "still_out" / "frame_0001.ply"), read_file(*dir_ / "plane.ply"));
}

TEST_F(Animate, TheVineSwaysAQuarterOfItsHeightAndStaysWholeAndApart) {
  const CliResult r =
      run_cli("animate --quilt " + at("plane.ply") + " --swatch-frames " + at("vine_frames") + " --swatch " +
              at("vine.ply") + " -o " + at("sway") + " --stats " + at("sway.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_file(*dir_ / "sway.json").find("\"dropped_meeting\": 0"), std::string::npos);
  const TriMesh rest = read_mesh(*dir_ / "plane.ply");
  double height = 0.0;
  for (const Vec3& p : rest.positions) height = std::max(height, p.z);
  double largest = 0.0;
  for (int k = 0; k < 8; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.ply", k);
    const TriMesh frame = read_mesh(*dir_ / "sway" / name);
    ASSERT_EQ(frame.num_vertices(), rest.num_vertices()) << name;
    for (size_t v = 0; v < rest.num_vertices(); ++v)
      largest = std::max(largest, glm::length(frame.positions[v] - rest.positions[v]));
    const ElementTopology topology = element_topology(frame);
    EXPECT_EQ(topology.closed_elements, topology.elements) << name;
    const FaceIntersections meet = find_intersecting_faces(frame, frame.elements);
    EXPECT_TRUE(meet.different_elements.empty()) << name;
    EXPECT_TRUE(meet.same_element.empty()) << name;
  }
  EXPECT_GE(largest, 0.25 * height);
}

TEST_F(Animate, OnASphereTheSwatchsHeightAxisFollowsTheNormal) {
  // A swatch frame lifted by 0.05 along its height axis (z): each vertex should move along the
  // sphere's normal at it, by 0.05 times the local scale of the shell: the copy's scale, grown by
  // (r / R)^(2/3) at radius r over a sphere of radius R (tangent directions stretch by r / R, the
  // normal one not; the frame's scale is the cube root of the three).
  fs::create_directories(*dir_ / "lift");
  TriMesh lifted = read_mesh(*dir_ / "vine.ply");
  for (Vec3& p : lifted.positions) p.z += 0.05;
  write_mesh(lifted, *dir_ / "lift" / "up.ply");
  const CliResult s =
      run_cli("synth --progress none --backend cpu --base '" + std::string(MESHQUILT_SOURCE_DIR) +
              "/data/sphere.off' --scale 0.5 --max-patches 6 --swatch " + at("vine.ply") +
              " --provenance -o " + at("sphere.ply"));
  ASSERT_EQ(s.exit_code, 0) << s.output;
  const CliResult r = run_cli("animate --keep-all --quilt " + at("sphere.ply") + " --swatch " +
                              at("vine.ply") + " --swatch-frames " + at("lift") + " -o " + at("lift_out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const TriMesh rest = read_mesh(*dir_ / "sphere.ply"), up = read_mesh(*dir_ / "lift_out" / "frame_0000.ply");
  const auto extent = [](const TriMesh& m) {
    Vec3 lo(1e300), hi(-1e300);
    for (const Vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return hi - lo;
  };
  // A copy's scale: 0.5 of the sphere's bounding-box diagonal over the swatch's longer side.
  const Vec3 swatch = extent(read_mesh(*dir_ / "vine.ply"));
  const TriMesh sphere = read_mesh(fs::path(MESHQUILT_SOURCE_DIR) / "data/sphere.off");
  const double scale = 0.5 * glm::length(extent(sphere)) / std::max(swatch.x, swatch.y);
  double radius = 0.0;
  for (const Vec3& p : sphere.positions)
    radius += glm::length(p) / static_cast<double>(sphere.num_vertices());
  int along = 0;
  std::vector<double> ratios;
  for (size_t v = 0; v < rest.num_vertices(); ++v) {
    const Vec3 move = up.positions[v] - rest.positions[v];
    along += glm::dot(glm::normalize(move), glm::normalize(rest.positions[v])) > 0.9;
    const double local = scale * std::cbrt(std::pow(glm::length(rest.positions[v]) / radius, 2.0));
    ratios.push_back(glm::length(move) / (0.05 * local));
  }
  EXPECT_GT(along, 0.9 * rest.num_vertices());
  // The model ignores the shell's own stretch: the median is on it, the spread within a fifth.
  std::sort(ratios.begin(), ratios.end());
  EXPECT_NEAR(ratios[ratios.size() / 2], 1.0, 0.05);
  const auto within =
      std::count_if(ratios.begin(), ratios.end(), [](double r) { return std::abs(r - 1.0) < 0.2; });
  EXPECT_GT(within, 0.8 * static_cast<double>(ratios.size()));
}

TEST_F(Animate, OverAMovingBaseAStillSwatchGivesTheBasesMotionAlone) {
  const CliResult s =
      run_cli("synth --progress none --backend cpu --base '" + std::string(MESHQUILT_SOURCE_DIR) +
              "/data/sphere.off' --scale 0.5 --max-patches 4 --swatch " + at("vine.ply") +
              " --write-texture " + at("moving.mqt") + " -o " + at("moving.ply"));
  ASSERT_EQ(s.exit_code, 0) << s.output;
  // Three poses of the sphere, stretched more and more along x.
  const TriMesh sphere = read_mesh(fs::path(MESHQUILT_SOURCE_DIR) / "data/sphere.off");
  fs::create_directories(*dir_ / "poses");
  for (int k = 0; k < 3; ++k) {
    TriMesh pose = sphere;
    for (Vec3& p : pose.positions) p.x *= 1.0 + 0.1 * k;
    write_mesh(pose, *dir_ / "poses" / ("pose_" + std::to_string(k) + ".ply"));
  }
  fs::create_directories(*dir_ / "still2");
  fs::copy_file(*dir_ / "vine.ply", *dir_ / "still2" / "a.ply", fs::copy_options::overwrite_existing);
  ASSERT_EQ(run_cli("animate --keep-all --quilt " + at("moving.mqt") + " --base-frames " + at("poses") +
                    " --swatch-frames " + at("still2") + " -o " + at("moving_out"))
                .exit_code,
            0);
  ASSERT_EQ(run_cli("embed --texture " + at("moving.mqt") + " --base-frames " + at("poses") + " -o " +
                    at("embedded"))
                .exit_code,
            0);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(read_file(*dir_ / "moving_out" / ("frame_000" + std::to_string(k) + ".ply")),
              read_file(*dir_ / "embedded" / ("pose_" + std::to_string(k) + ".ply")))
        << "frame " << k;
}

}  // namespace
}  // namespace meshquilt::test
