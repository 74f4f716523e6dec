// `meshquilt swatch`: every kind writes a loadable mesh; random kinds are reproducible by seed;
// invalid options exit with the documented code, one line, and no output file.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "exit_codes.h"
#include "mesh/mesh_io.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::run_cli;
using test::scratch_dir;
using test::write_file;

int code(cli::ExitCode c) { return static_cast<int>(c); }

int elements_of(const TriMesh& m) {
  int count = 0;
  for (int32_t e : m.elements) count = std::max(count, e + 1);
  return count;
}

TEST(SwatchCli, EveryKindWritesItsSmallPreset) {
  const fs::path dir = scratch_dir("swatch_cli_kinds");
  struct Case {
    std::string args;
    int elements;
  };
  const Case cases[] = {
      {"chainmail --preset small --columns 3", 12},
      {"weave --preset small --pattern twill:2/3", 10},
      {"weave --preset small --only wefts", 4},
      {"wire --preset small", 10},
      {"wire --preset small --wires 3 --only warps", 3},
      {"fruit --preset small --columns 3", 6},
      {"nuts --preset small --seed 9", 4},
      {"heightfield --preset small", 1},
      {"heightfield --preset small --open", 1},
      {"heightfield --preset small --tiles 4", 16},
  };
  int n = 0;
  for (const Case& c : cases) {
    const fs::path out = dir / ("out" + std::to_string(n++) + ".ply");
    const auto r = run_cli("swatch " + c.args + " -o '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << c.args << ": " << r.output;
    const TriMesh m = read_mesh(out);
    EXPECT_EQ(elements_of(m), c.elements) << c.args;
    EXPECT_LE(m.num_faces(), 2600u) << c.args;
  }
  fs::remove_all(dir);
}

// Generators name the parameters at fault; the command line names them as its options.
TEST(SwatchCli, MessagesNameTheOptions) {
  const auto dir = scratch_dir("swatch_cli_messages");
  const std::string out = " -o '" + (dir / "x.ply").string() + "'";
  const struct {
    std::string args, message;
  } cases[] = {
      {"chainmail --rows 5", "meshquilt: chainmail: --rows must be an even number >= 2 (got 5)"},
      {"chainmail --pitch-x 0", "meshquilt: chainmail: --pitch-x and --pitch-y must be positive"},
      {"weave --pattern satin:3/1", "meshquilt: weave: --pattern satin:3/1 is not a regular satin"},
      {"nuts --size-variation 0.9", "meshquilt: nuts: --size-variation must lie in [0, 0.5]"},
  };
  for (const auto& c : cases) {
    const auto run = run_cli("swatch " + c.args + out);
    EXPECT_EQ(run.exit_code, code(cli::ExitCode::invalid_option)) << c.args;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.args << ": " << run.output;
  }
}

TEST(SwatchCli, SeedsReproduceBytes) {
  const fs::path dir = scratch_dir("swatch_cli_seed");
  for (const std::string kind : {"fruit", "nuts"}) {
    const std::string base = "swatch " + kind + " --preset small -o '" + dir.string() + "/";
    ASSERT_EQ(run_cli(base + "a.ply' --seed 5").exit_code, 0);
    ASSERT_EQ(run_cli(base + "b.ply' --seed 5").exit_code, 0);
    ASSERT_EQ(run_cli(base + "c.ply' --seed 6").exit_code, 0);
    EXPECT_EQ(read_file(dir / "a.ply"), read_file(dir / "b.ply")) << kind;
    EXPECT_NE(read_file(dir / "a.ply"), read_file(dir / "c.ply")) << kind;
  }
  fs::remove_all(dir);
}

TEST(SwatchCli, InvalidOptionsFailWithoutWriting) {
  const fs::path dir = scratch_dir("swatch_cli_errors");
  write_file(dir / "corrupt.pgm", "P5\n8 8\n255\nxx");
  write_file(dir / "photo.pgm", "\x89PNG....");
  struct Case {
    std::string args;
    int exit_code;
  };
  const Case cases[] = {
      {"weave --pattern satin:3/1", code(cli::ExitCode::invalid_option)},
      {"weave --pattern twill:2/0", code(cli::ExitCode::invalid_option)},
      {"weave --pattern herringbone", code(cli::ExitCode::invalid_option)},
      {"weave --pattern twill:2/3 --warps 7", code(cli::ExitCode::invalid_option)},
      {"weave --yarn-radius 0.6", code(cli::ExitCode::invalid_option)},
      {"weave --only diagonal", code(cli::ExitCode::usage)},
      {"wire --radius 0.6", code(cli::ExitCode::invalid_option)},
      {"wire --crimp 0.05", code(cli::ExitCode::invalid_option)},
      {"wire --wires 0", code(cli::ExitCode::invalid_option)},
      {"weave --pattern '" + (dir / "missing.pbm").string() + "'", code(cli::ExitCode::file_unreadable)},
      {"chainmail --wire-radius 0.4", code(cli::ExitCode::invalid_option)},
      {"chainmail --rows 5", code(cli::ExitCode::invalid_option)},
      {"chainmail --rows many", code(cli::ExitCode::usage)},
      {"nuts --hole-radius 2", code(cli::ExitCode::invalid_option)},
      {"fruit --subdivisions 9", code(cli::ExitCode::invalid_option)},
      {"heightfield --image '" + (dir / "missing.pgm").string() + "'", code(cli::ExitCode::file_unreadable)},
      {"heightfield --image '" + (dir / "corrupt.pgm").string() + "'", code(cli::ExitCode::file_unreadable)},
      {"heightfield --image '" + (dir / "photo.pgm").string() + "'", code(cli::ExitCode::unknown_format)},
      {"heightfield --height 50", code(cli::ExitCode::invalid_option)},
      {"teapot", code(cli::ExitCode::usage)},
      {"fruit --preset huge", code(cli::ExitCode::usage)},
  };
  for (const Case& c : cases) {
    const fs::path out = dir / "out.ply";
    const auto r = run_cli("swatch " + c.args + " -o '" + out.string() + "'");
    EXPECT_EQ(r.exit_code, c.exit_code) << c.args << ": " << r.output;
    EXPECT_FALSE(fs::exists(out)) << c.args;
    if (c.exit_code != code(cli::ExitCode::usage)) {
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.args << ": " << r.output;
    }
  }
  // Nothing else was left in the folder either (no temporary files).
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2u);
  // A missing -o is a usage error.
  EXPECT_EQ(run_cli("swatch nuts").exit_code, code(cli::ExitCode::usage));
  fs::remove_all(dir);
}

TEST(SwatchCli, UnwritableOutputFails) {
  const auto r = run_cli("swatch nuts --preset small -o /nonexistent-dir/out.ply");
  EXPECT_EQ(r.exit_code, code(cli::ExitCode::write_failed)) << r.output;
  const fs::path dir = scratch_dir("swatch_cli_format");
  const auto s = run_cli("swatch nuts --preset small -o '" + (dir / "out.xyz").string() + "'");
  EXPECT_EQ(s.exit_code, code(cli::ExitCode::unknown_format)) << s.output;
  EXPECT_FALSE(fs::exists(dir / "out.xyz"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace meshquilt
