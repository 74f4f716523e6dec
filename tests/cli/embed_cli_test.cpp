// `synth --write-texture` and `meshquilt embed`: the texture-space file round trip, re-embedding
// over an edited base, and bad input (a one-line error, a distinct exit code, nothing written).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>

#include "mesh/mesh_io.h"
#include "spatial/intersecting_pairs.h"
#include "support/run_cli.h"
#include "support/surface_fixtures.h"

namespace meshquilt::test {
namespace {

void write_off(const std::filesystem::path& file, const TriMesh& m) {
  std::ofstream out(file);
  out.precision(17);
  out << "OFF\n" << m.num_vertices() << " " << m.num_faces() << " 0\n";
  for (const Vec3& p : m.positions) out << p.x << " " << p.y << " " << p.z << "\n";
  for (const Tri& t : m.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

TriMesh moved(TriMesh m, Vec3 (*motion)(const Vec3&)) {
  for (Vec3& p : m.positions) p = motion(p);
  return m;
}

Vec3 squash(const Vec3& p) { return Vec3(1.2 * p.x, p.y, 0.9 * p.z); }

// One synthesis over a small sphere for the whole suite.
class Embed : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(scratch_dir("embed_cli"));
    base_ = new TriMesh(icosphere(2));
    write_off(*dir_ / "sphere.off", *base_);
    const CliResult r =
        run_cli("synth --progress none --backend cpu --base '" + (*dir_ / "sphere.off").string() +
                "' --scale 0.35 --max-patches 8 --write-texture '" + (*dir_ / "t.mqt").string() + "' -o '" +
                (*dir_ / "synth.ply").string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete base_;
  }
  // Runs embed; returns its exit code and output.
  static CliResult embed(const std::filesystem::path& texture, const std::filesystem::path& base,
                         const std::filesystem::path& out) {
    return run_cli("embed --texture '" + texture.string() + "' --base '" + base.string() + "' -o '" +
                   out.string() + "'");
  }
  // Embeds the suite's texture over `edited` (written as NAME.off); returns the output as NAME.ply.
  static TriMesh embed_over(const std::string& name, const TriMesh& edited) {
    write_off(*dir_ / (name + ".off"), edited);
    const CliResult r = embed(*dir_ / "t.mqt", *dir_ / (name + ".off"), *dir_ / (name + ".ply"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_mesh(*dir_ / (name + ".ply"));
  }
  static std::filesystem::path* dir_;
  static TriMesh* base_;
};
std::filesystem::path* Embed::dir_ = nullptr;
TriMesh* Embed::base_ = nullptr;

TEST_F(Embed, OverTheSameBaseGivesTheSynthesizedOutput) {
  const CliResult r = embed(*dir_ / "t.mqt", *dir_ / "sphere.off", *dir_ / "same.ply");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const TriMesh a = read_mesh(*dir_ / "synth.ply"), b = read_mesh(*dir_ / "same.ply");
  ASSERT_GT(a.num_faces(), 1000u);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST_F(Embed, OverARigidlyMovedBaseGivesTheMovedOutput) {
  const TriMesh a = read_mesh(*dir_ / "synth.ply"), b = embed_over("rigid", moved(*base_, rigid_motion));
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  double worst = 0.0;
  for (size_t v = 0; v < a.num_vertices(); ++v)
    worst = std::max(worst, glm::distance(rigid_motion(a.positions[v]), b.positions[v]));
  EXPECT_LT(worst, 1e-9);  // of a unit sphere
}

TEST_F(Embed, OverASquashedBaseFlipsNoFaceAndAddsNoIntersection) {
  const TriMesh a = read_mesh(*dir_ / "synth.ply"), b = embed_over("squashed", moved(*base_, squash));
  ASSERT_EQ(a.num_faces(), b.num_faces());
  // Orientation against the surface below: the gradient of the (squashed) sphere's implicit
  // function at the face centroid.
  int flipped = 0;
  for (size_t f = 0; f < a.num_faces(); ++f) {
    const Tri& t = a.triangles[f];
    const Vec3 na = glm::cross(a.positions[t[1]] - a.positions[t[0]], a.positions[t[2]] - a.positions[t[0]]);
    const Vec3 nb = glm::cross(b.positions[t[1]] - b.positions[t[0]], b.positions[t[2]] - b.positions[t[0]]);
    const Vec3 ca = (a.positions[t[0]] + a.positions[t[1]] + a.positions[t[2]]) / 3.0;
    const Vec3 cb = (b.positions[t[0]] + b.positions[t[1]] + b.positions[t[2]]) / 3.0;
    const Vec3 ga = ca, gb(cb.x / (1.2 * 1.2), cb.y, cb.z / (0.9 * 0.9));
    const double sa = glm::dot(na, glm::normalize(ga)) / glm::length(na);
    const double sb = glm::dot(nb, glm::normalize(gb)) / glm::length(nb);
    // Faces nearly perpendicular to the surface may tip either way; a flip is a clear reversal.
    if (std::abs(sa) > 0.2 && sa * sb < 0.0) ++flipped;
  }
  EXPECT_EQ(flipped, 0);
  const auto crossings = [](const TriMesh& m) {
    return intersecting_face_pairs(m, m.elements, IntersectionScope::different_elements).size();
  };
  EXPECT_LE(crossings(b), crossings(a));
}

TEST_F(Embed, NormalDisplacementOfTheSameTextureKeepsItsTopology) {
  const CliResult r =
      run_cli("embed --embed normal --texture '" + (*dir_ / "t.mqt").string() + "' --base '" +
              (*dir_ / "sphere.off").string() + "' -o '" + (*dir_ / "normal.ply").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const TriMesh a = read_mesh(*dir_ / "synth.ply"), b = read_mesh(*dir_ / "normal.ply");
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_NE(a.positions, b.positions);
  // On a sphere both embeddings put a vertex at about the same height: within a tenth of the
  // layer (0.35 / 4 rings of the unit sphere's diagonal, roughly).
  double worst = 0.0;
  for (size_t v = 0; v < a.num_vertices(); ++v)
    worst = std::max(worst, std::abs(glm::length(a.positions[v]) - glm::length(b.positions[v])));
  EXPECT_LT(worst, 0.05);
}

// Frame k of a bend that grows over the sequence: each point turned about z by an angle that
// grows with x, up to 60 degrees at the last frame.
TriMesh bent(const TriMesh& m, int k, int frames) {
  TriMesh out = m;
  for (Vec3& p : out.positions) {
    const double angle = (1.0472 * k / (frames - 1)) * 0.5 * (p.x + 1.0);
    p = Vec3(std::cos(angle) * p.x - std::sin(angle) * p.y, std::sin(angle) * p.x + std::cos(angle) * p.y, p.z);
  }
  return out;
}

TEST_F(Embed, EveryFrameOfAMovingBaseEqualsASingleEmbedAndResumes) {
  const int frames = 24;
  const auto in = *dir_ / "walk", out = *dir_ / "walk_out";
  std::filesystem::create_directories(in);
  for (int k = 0; k < frames; ++k) write_off(in / ("pose_" + std::to_string(k) + ".off"), bent(*base_, k, frames));
  const auto run = [&] {
    return run_cli("embed --texture '" + (*dir_ / "t.mqt").string() + "' --base-frames '" + in.string() + "' -o '" +
                   out.string() + "' --stats '" + (*dir_ / "frames.json").string() + "'");
  };
  const CliResult r = run();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (int k = 0; k < frames; ++k) {
    const auto single = *dir_ / ("single_" + std::to_string(k) + ".ply");
    ASSERT_EQ(embed(*dir_ / "t.mqt", in / ("pose_" + std::to_string(k) + ".off"), single).exit_code, 0);
    EXPECT_EQ(read_file(out / ("pose_" + std::to_string(k) + ".ply")), read_file(single)) << "frame " << k;
  }
  const std::string stats = read_file(*dir_ / "frames.json");
  EXPECT_NE(stats.find("\"made\": 24"), std::string::npos) << stats;
  // A rerun keeps what is there and makes only a frame that went missing.
  std::filesystem::remove(out / "pose_7.ply");
  const CliResult again = run();
  ASSERT_EQ(again.exit_code, 0) << again.output;
  const std::string resumed = read_file(*dir_ / "frames.json");
  EXPECT_NE(resumed.find("\"made\": 1"), std::string::npos) << resumed;
  EXPECT_EQ(read_file(out / "pose_7.ply"), read_file(*dir_ / "single_7.ply"));
  // A frame of other connectivity stops the run with exit code 15, naming it.
  write_off(in / "pose_30.off", icosphere(1));
  const CliResult bad = run();
  EXPECT_EQ(bad.exit_code, 15) << bad.output;
  EXPECT_NE(bad.output.find("pose_30.off"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(out / "pose_30.ply"));
}

class EmbedBadInput : public Embed {
 protected:
  void SetUp() override {
    output_ = *dir_ / "kept.ply";
    write_file(output_, "previous good output");
  }
  void expect_failure(const std::filesystem::path& texture, const std::filesystem::path& base, int code,
                      const std::string& needle) {
    const CliResult r = embed(texture, base, output_);
    EXPECT_EQ(r.exit_code, code) << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(read_file(output_), "previous good output");
  }
  std::filesystem::path output_;
};

TEST_F(EmbedBadInput, TruncatedTexture) {
  const std::string bytes = read_file(*dir_ / "t.mqt");
  write_file(*dir_ / "cut.mqt", bytes.substr(0, bytes.size() / 2));
  expect_failure(*dir_ / "cut.mqt", *dir_ / "sphere.off", 14, "cut.mqt");
}

TEST_F(EmbedBadInput, CorruptTexture) {
  std::string bytes = read_file(*dir_ / "t.mqt");
  bytes[bytes.size() / 2] ^= 0x5a;
  write_file(*dir_ / "corrupt.mqt", bytes);
  expect_failure(*dir_ / "corrupt.mqt", *dir_ / "sphere.off", 14, "corrupt.mqt");
}

TEST_F(EmbedBadInput, NotATextureFile) {
  expect_failure(*dir_ / "sphere.off", *dir_ / "sphere.off", 14, "sphere.off");
}

TEST_F(EmbedBadInput, UnknownEmbedding) {
  const CliResult r =
      run_cli("embed --embed sideways --texture '" + (*dir_ / "t.mqt").string() + "' --base '" +
              (*dir_ / "sphere.off").string() + "' -o '" + output_.string() + "'");
  EXPECT_EQ(r.exit_code, 6) << r.output;
  EXPECT_EQ(read_file(output_), "previous good output");
}

TEST_F(EmbedBadInput, BaseWithAnotherFaceCount) {
  write_off(*dir_ / "coarse.off", icosphere(1));
  expect_failure(*dir_ / "t.mqt", *dir_ / "coarse.off", 15, "coarse.off");
}

TEST_F(EmbedBadInput, BaseWithOtherConnectivity) {
  // The same vertices and face count, one edge flipped.
  TriMesh flipped = *base_;
  const Tri f = flipped.triangles[0];  // (a, b, c); its neighbour across a-b is (b, a, d)
  for (Tri& g : flipped.triangles)
    for (int k = 0; k < 3; ++k)
      if (g[k] == f[1] && g[(k + 1) % 3] == f[0]) {
        const int32_t d = g[(k + 2) % 3];
        flipped.triangles[0] = {f[0], d, f[2]};
        g = {f[1], f[2], d};
        goto done;
      }
done:
  write_off(*dir_ / "flipped.off", flipped);
  expect_failure(*dir_ / "t.mqt", *dir_ / "flipped.off", 15, "flipped.off");
}

}  // namespace
}  // namespace meshquilt::test
