// `meshquilt swatch check FILE`: a good swatch passes; open, intersecting and thick ones are
// refused with one line per finding and the swatch_unfit exit code; an unreadable file gives the
// usual one-line error.
#include <algorithm>
#include <filesystem>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "exit_codes.h"
#include "mesh/mesh_io.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::scratch_dir;

int code(cli::ExitCode c) { return static_cast<int>(c); }

class SwatchCheckCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir("swatch_check_cli");
    good_ = dir_ / "good.ply";
    ASSERT_EQ(run_cli("swatch chainmail --preset small -o '" + good_.string() + "'").exit_code, 0);
    mail_ = read_mesh(good_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  test::CliResult check(const TriMesh& mesh, const std::string& name) {
    const fs::path file = dir_ / name;
    write_mesh(mesh, file);
    return run_cli("swatch check '" + file.string() + "'");
  }

  fs::path dir_, good_;
  TriMesh mail_;
};

TEST_F(SwatchCheckCli, OurSmallChainMailIsFine) {
  const auto run = run_cli("swatch check '" + good_.string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("good.ply: fine: 8 closed elements"), std::string::npos) << run.output;
}

TEST_F(SwatchCheckCli, OpenElementsAreCounted) {
  // A mail with rings away from its border; two faces of the ring nearest the middle gone.
  const fs::path wide = dir_ / "wide.ply";
  ASSERT_EQ(run_cli("swatch chainmail --preset small --rows 6 --columns 3 -o '" + wide.string() + "'").exit_code, 0);
  TriMesh open = read_mesh(wide);
  Vec3 middle(0.0);
  for (const Vec3& p : open.positions) middle += p / double(open.positions.size());
  size_t nearest = 0;
  for (size_t f = 0; f < open.num_faces(); ++f)
    if (glm::length(open.positions[open.triangles[f][0]] - middle) <
        glm::length(open.positions[open.triangles[nearest][0]] - middle))
      nearest = f;
  open.triangles.erase(open.triangles.begin() + nearest, open.triangles.begin() + nearest + 2);
  open.elements.erase(open.elements.begin() + nearest, open.elements.begin() + nearest + 2);
  open.sources.clear();
  const auto run = check(open, "open.ply");
  EXPECT_EQ(run.exit_code, code(cli::ExitCode::swatch_unfit)) << run.output;
  EXPECT_NE(run.output.find("open.ply: 1 open element of 18"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("cut open by the border"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("meshquilt: "), std::string::npos) << run.output;
}

TEST_F(SwatchCheckCli, ElementsPassingThroughEachOtherAreCounted) {
  // A second copy of every ring moved a quarter of a ring along x: copies cut through rings.
  TriMesh doubled = mail_;
  const size_t n = mail_.positions.size();
  for (size_t v = 0; v < n; ++v) doubled.positions.push_back(mail_.positions[v] + Vec3(0.25, 0.0, 0.0));
  for (const Tri& t : mail_.triangles)
    doubled.triangles.push_back({t[0] + int32_t(n), t[1] + int32_t(n), t[2] + int32_t(n)});
  doubled.elements.clear();
  doubled.sources.clear();
  const auto run = check(doubled, "doubled.ply");
  EXPECT_EQ(run.exit_code, code(cli::ExitCode::swatch_unfit)) << run.output;
  EXPECT_NE(run.output.find("of elements intersecting ("), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("open element"), std::string::npos) << run.output;
}

TEST_F(SwatchCheckCli, ThickLayoutsAreRefused) {
  TriMesh tall = mail_;
  for (Vec3& p : tall.positions) p.z *= 8.0;
  const auto run = check(tall, "tall.ply");
  EXPECT_EQ(run.exit_code, code(cli::ExitCode::swatch_unfit)) << run.output;
  EXPECT_NE(run.output.find("tall.ply: not thin along z"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("will not quilt well (1 problem)"), std::string::npos) << run.output;
}

TEST_F(SwatchCheckCli, ElementsCutByTheBorderAreNamedSo) {
  // Faces past the middle of x dropped: the rings there are cut open by the new border.
  TriMesh cut;
  cut.positions = mail_.positions;
  double lo = 1e300, hi = -1e300;
  for (const Vec3& p : mail_.positions) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  for (const Tri& t : mail_.triangles) {
    const double x = (mail_.positions[t[0]].x + mail_.positions[t[1]].x + mail_.positions[t[2]].x) / 3.0;
    if (x < 0.5 * (lo + hi)) cut.triangles.push_back(t);
  }
  const auto run = check(cut, "cut.ply");
  EXPECT_EQ(run.exit_code, code(cli::ExitCode::swatch_unfit)) << run.output;
  EXPECT_NE(run.output.find("cut open by the border"), std::string::npos) << run.output;
}

TEST_F(SwatchCheckCli, UnreadableFileIsOneLine) {
  const auto run = run_cli("swatch check '" + (dir_ / "missing.ply").string() + "'");
  EXPECT_EQ(run.exit_code, code(cli::ExitCode::file_unreadable)) << run.output;
  EXPECT_EQ(run.output.rfind("meshquilt: " + (dir_ / "missing.ply").string() + ": ", 0), 0u) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

}  // namespace
}  // namespace meshquilt
