// Bad input to `meshquilt synth`: a one-line error naming the file or option, a distinct exit
// code, and a pre-existing output file left exactly as it was.
#include <gtest/gtest.h>

#include "support/run_cli.h"

namespace meshquilt::test {
namespace {

// A closed tetrahedron with some thickness in every direction: a valid swatch.
const char* kTetrahedron = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0.3\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

class SynthBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    output_ = dir_ / "out.ply";
    write_file(output_, "previous good output");
  }
  // Runs synth and checks exit code, a single-line message containing `needle`, and the output.
  void expect_failure(const std::string& args, int code, const std::string& needle) {
    const CliResult r = run_cli("synth --progress none " + args + " -o '" + output_.string() + "'");
    EXPECT_EQ(r.exit_code, code) << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(read_file(output_), "previous good output");
  }
  std::filesystem::path swatch(const std::string& name, const std::string& text) {
    const auto file = dir_ / name;
    write_file(file, text);
    return file;
  }
  std::filesystem::path dir_, output_;
};

TEST_F(SynthBadInput, MissingFile) { expect_failure("--swatch " + (dir_ / "nope.obj").string(), 3, "nope.obj"); }

TEST_F(SynthBadInput, UnknownFormat) {
  expect_failure("--swatch " + swatch("s.xyz", kTetrahedron).string(), 4, "s.xyz");
}

TEST_F(SynthBadInput, NoFaces) {
  expect_failure("--swatch " + swatch("s.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n").string(), 5, "s.off");
}

TEST_F(SynthBadInput, NotANumber) {
  expect_failure("--swatch " + swatch("s.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n").string(), 5, "s.off");
}

TEST_F(SynthBadInput, Truncated) {
  expect_failure("--swatch " + swatch("s.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n").string(), 5, "s.off");
}

TEST_F(SynthBadInput, ZeroThicknessSwatch) {
  // Flat: every vertex at z = 0.
  expect_failure("--swatch " + swatch("flat.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n").string(),
                 5, "flat.off");
}

TEST_F(SynthBadInput, BadPlane) { expect_failure("--plane 4by4", 6, "--plane"); }

TEST_F(SynthBadInput, NegativePlane) { expect_failure("--plane -1x2", 6, "--plane"); }

TEST_F(SynthBadInput, BadBackend) { expect_failure("--backend cuda", 6, "--backend"); }

TEST_F(SynthBadInput, UnknownOption) { expect_failure("--frobnicate 3", 2, "frobnicate"); }

// Curved surfaces: bad bases and bad field files.
const char* kBaseTetrahedron = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

TEST_F(SynthBadInput, NonManifoldBase) {
  // Three triangles on the edge (0, 1).
  const auto base = swatch("fan.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  expect_failure("--base " + base.string(), 5, "fan.off: non-manifold edge shared by 3 faces (faces 0, 1, 2)");
}

TEST_F(SynthBadInput, EmptyBase) {
  expect_failure("--base " + swatch("empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n").string(), 5, "empty.off");
}

TEST_F(SynthBadInput, BaseWithNaN) {
  expect_failure("--base " + swatch("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n").string(), 5,
                 "nan.off");
}

TEST_F(SynthBadInput, MissingBase) { expect_failure("--base " + (dir_ / "nope.off").string(), 3, "nope.off"); }

TEST_F(SynthBadInput, MalformedField) {
  const auto base = swatch("tet.off", kBaseTetrahedron);
  expect_failure("--base " + base.string() + " --field " + swatch("f.json", "{\"directions\": [").string(), 6,
                 "f.json: not valid JSON");
}

TEST_F(SynthBadInput, FieldNamesAMissingVertex) {
  const auto base = swatch("tet.off", kBaseTetrahedron);
  const auto field = swatch("f.json", R"({"directions": [{"vertex": 99, "direction": [1, 0, 0]}]})");
  expect_failure("--base " + base.string() + " --field " + field.string(), 6, "vertex 99 does not exist");
}

TEST_F(SynthBadInput, MissingField) {
  const auto base = swatch("tet.off", kBaseTetrahedron);
  expect_failure("--base " + base.string() + " --field " + (dir_ / "nope.json").string(), 3, "nope.json");
}

TEST_F(SynthBadInput, FieldWithoutBase) { expect_failure("--field f.json", 6, "--base"); }

TEST_F(SynthBadInput, BadScale) {
  expect_failure("--base " + swatch("tet.off", kBaseTetrahedron).string() + " --scale 0", 6, "--scale");
}

TEST_F(SynthBadInput, BadSizeHold) {
  expect_failure("--plane 2x2 --size-hold 0", 6, "--size-hold");
  expect_failure("--plane 2x2 --size-hold -1", 6, "--size-hold");
  expect_failure("--plane 2x2 --size-hold 2000", 6, "--size-hold");
  expect_failure("--plane 2x2 --cone-spread 0.5", 6, "--cone-spread");
  expect_failure("--plane 2x2 --cone-spread 2000", 6, "--cone-spread");
}

TEST(SynthBadOutput, UnknownOutputFormat) {
  const auto dir = scratch_dir("unknown_output");
  const CliResult r = run_cli("synth --progress none -o '" + (dir / "out.xyz").string() + "'");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("out.xyz"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.xyz"));
}

TEST(SynthBadOutput, MissingFolder) {
  const auto dir = scratch_dir("missing_folder");
  const CliResult r = run_cli("synth --progress none -o '" + (dir / "no" / "out.ply").string() + "'");
  EXPECT_EQ(r.exit_code, 7) << r.output;
  EXPECT_NE(r.output.find("out.ply"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace meshquilt::test
