// `meshquilt edit` end to end: aging and removal by source on a planar result and on a
// texture-space file, and bad requests (one line, a distinct exit code, nothing written).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "mesh/mesh_io.h"
#include "support/run_cli.h"
#include "support/surface_fixtures.h"

namespace meshquilt::test {
namespace {

// Each element's faces as corner positions, in face order.
std::map<int32_t, std::vector<std::array<Vec3, 3>>> faces_by_element(const TriMesh& m) {
  std::map<int32_t, std::vector<std::array<Vec3, 3>>> out;
  for (size_t f = 0; f < m.num_faces(); ++f)
    out[m.elements[f]].push_back(
        {m.positions[m.triangles[f][0]], m.positions[m.triangles[f][1]], m.positions[m.triangles[f][2]]});
  return out;
}

class Edit : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(scratch_dir("edit_cli"));
    const CliResult plane = run_cli("synth --progress none --backend cpu --plane 3x3 -o '" +
                                    (*dir_ / "plane.ply").string() + "'");
    ASSERT_EQ(plane.exit_code, 0) << plane.output;
    const TriMesh sphere = icosphere(2);
    std::string off =
        "OFF\n" + std::to_string(sphere.num_vertices()) + " " + std::to_string(sphere.num_faces()) + " 0\n";
    char line[128];
    for (const Vec3& p : sphere.positions) {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
      off += line;
    }
    for (const Tri& t : sphere.triangles)
      off += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    write_file(*dir_ / "sphere.off", off);
    const CliResult curved =
        run_cli("synth --progress none --backend cpu --base '" + (*dir_ / "sphere.off").string() +
                "' --scale 0.35 --max-patches 8 --write-texture '" + (*dir_ / "t.mqt").string() + "' -o '" +
                (*dir_ / "sphere.ply").string() + "'");
    ASSERT_EQ(curved.exit_code, 0) << curved.output;
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string at(const std::string& name) { return "'" + (*dir_ / name).string() + "'"; }
  static std::filesystem::path* dir_;
};
std::filesystem::path* Edit::dir_ = nullptr;

TEST_F(Edit, AgingRemovesTenPercentAndKeepsEveryOtherElementByteForByte) {
  const CliResult r = run_cli("edit " + at("plane.ply") + " -o " + at("aged.ply") + " --age 0.1 --seed 3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto before = faces_by_element(read_mesh(*dir_ / "plane.ply"));
  const auto after = faces_by_element(read_mesh(*dir_ / "aged.ply"));
  const double removed = 1.0 - static_cast<double>(after.size()) / static_cast<double>(before.size());
  EXPECT_NEAR(removed, 0.1, 0.01) << before.size() << " -> " << after.size();
  for (const auto& [id, faces] : after) {
    ASSERT_TRUE(before.count(id)) << id;
    EXPECT_EQ(faces, before.at(id)) << "element " << id;
  }
}

TEST_F(Edit, RemovingBySourceFromATextureFileAndPlacingItMatchesEditingTheMesh) {
  ASSERT_EQ(run_cli("edit " + at("t.mqt") + " -o " + at("no0.mqt") + " --remove-source 0").exit_code, 0);
  ASSERT_EQ(run_cli("embed --texture " + at("no0.mqt") + " --base " + at("sphere.off") + " -o " +
                    at("no0_embedded.ply"))
                .exit_code,
            0);
  ASSERT_EQ(run_cli("edit " + at("sphere.ply") + " -o " + at("no0.ply") + " --remove-source 0").exit_code, 0);
  const TriMesh embedded = read_mesh(*dir_ / "no0_embedded.ply"), edited = read_mesh(*dir_ / "no0.ply");
  const TriMesh original = read_mesh(*dir_ / "sphere.ply");
  ASSERT_LT(edited.num_faces(), original.num_faces());
  EXPECT_EQ(std::set<int32_t>(edited.sources.begin(), edited.sources.end()).count(0), 0u);
  EXPECT_EQ(faces_by_element(embedded), faces_by_element(edited));
}

TEST_F(Edit, BadRequestsFailWithOneLineAndWriteNothing) {
  const auto fails = [&](const std::string& args, int code, const std::string& says) {
    const CliResult r = run_cli("edit " + args);
    EXPECT_EQ(r.exit_code, code) << args << ": " << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  };
  fails(at("t.mqt") + " -o " + at("bad1.ply"), 6, "needs --base");
  fails(at("plane.ply") + " -o " + at("bad2.mqt"), 6, "can only be edited from one");
  fails(at("plane.ply") + " -o " + at("bad3.ply") + " --age 2", 6, "--age");
  fails(at("plane.ply") + " -o " + at("bad4.ply") + " --remove-elements 4-x", 6, "--remove-elements");
  fails(at("plane.ply") + " -o " + at("bad5.xyz"), 4, "unknown mesh format");
  fails(at("missing.ply") + " -o " + at("bad6.ply"), 3, "missing.ply");
  for (const char* name : {"bad1.ply", "bad2.mqt", "bad3.ply", "bad4.ply", "bad5.xyz", "bad6.ply"})
    EXPECT_FALSE(std::filesystem::exists(*dir_ / name)) << name;
}

}  // namespace
}  // namespace meshquilt::test
