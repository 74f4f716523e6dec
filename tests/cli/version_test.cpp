// `meshquilt --version` prints the version the Python package and the add-on declare.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "support/run_cli.h"

namespace meshquilt {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Version, PrintedAsThePackagesDeclareIt) {
  const test::CliResult r = test::run_cli("--version");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::smatch printed;
  ASSERT_TRUE(std::regex_search(r.output, printed, std::regex("^meshquilt (\\d+)\\.(\\d+)\\.(\\d+)\\n$"))) << r.output;
  const std::string source = MESHQUILT_SOURCE_DIR;
  const std::string pyproject = read_text(source + "/pyproject.toml");
  EXPECT_NE(pyproject.find("version = \"" + printed[1].str() + "." + printed[2].str() + "." + printed[3].str() + "\""),
            std::string::npos);
  const std::string addon = read_text(source + "/blender/meshquilt_blender/__init__.py");
  EXPECT_NE(addon.find("\"version\": (" + printed[1].str() + ", " + printed[2].str() + ", " + printed[3].str() + ")"),
            std::string::npos);
}

}  // namespace
}  // namespace meshquilt
