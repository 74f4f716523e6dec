// Netpbm reading (every variant against the same hand-made image) and weave pattern parsing
// (families checked against their definitions, invalid ones rejected with the right code).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>

#include <gtest/gtest.h>

#include <optional>

#include "core/error.h"
#include "swatch/netpbm.h"
#include "swatch/weave_pattern.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

class NetpbmFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("meshquilt_swatch_patterns_" + std::string(
        ::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }
  fs::path dir_;
};

// A 10 x 2 bitmap: row 0 = 1100000001, row 1 = 0011111110 (1 = black). Ten columns make the
// raw PBM rows two bytes long, with padding bits.
const int kBits[2][10] = {{1, 1, 0, 0, 0, 0, 0, 0, 0, 1}, {0, 0, 1, 1, 1, 1, 1, 1, 1, 0}};

void expect_bitmap(const GrayImage& image) {
  ASSERT_EQ(image.width, 10);
  ASSERT_EQ(image.height, 2);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 10; ++c) EXPECT_EQ(image.at(c, r), kBits[r][c] ? 0.0 : 1.0) << c << "," << r;
}

TEST_F(NetpbmFiles, PlainAndRawBitmapsAgree) {
  expect_bitmap(read_netpbm(write("a.pbm", "P1\n# comment\n10 2\n1 1 0 0 0 0 0 0 0 1\n0011111110\n")));
  // Raw rows: 11000000 01xxxxxx, 00111111 10xxxxxx (padding bits set to check they are ignored).
  const std::string raw = std::string("P4\n10 2\n") + char(0xC0) + char(0x7F) + char(0x3F) + char(0xBF);
  expect_bitmap(read_netpbm(write("b.pbm", raw)));
}

TEST_F(NetpbmFiles, PlainAndRawGraymapsAgree) {
  const GrayImage plain = read_netpbm(write("a.pgm", "P2 3 2 #c\n 255\n0 51 255\n102 204 255\n"));
  ASSERT_EQ(plain.width, 3);
  ASSERT_EQ(plain.height, 2);
  EXPECT_DOUBLE_EQ(plain.at(1, 0), 51.0 / 255.0);
  EXPECT_DOUBLE_EQ(plain.at(0, 1), 102.0 / 255.0);
  std::string raw = "P5\n3 2\n255\n";
  for (int v : {0, 51, 255, 102, 204, 255}) raw += static_cast<char>(v);
  EXPECT_EQ(read_netpbm(write("b.pgm", raw)).values, plain.values);
  // 16-bit samples are big-endian.
  std::string wide = "P5\n3 2\n65535\n";
  for (int v : {0, 51, 255, 102, 204, 255}) wide += std::string{static_cast<char>((v * 257) >> 8), static_cast<char>((v * 257) & 0xFF)};
  const GrayImage w = read_netpbm(write("c.pgm", wide));
  for (size_t k = 0; k < plain.values.size(); ++k) EXPECT_NEAR(w.values[k], plain.values[k], 1e-15);
}

TEST_F(NetpbmFiles, ColourImagesBecomeLumaAndKeepTheirColours) {
  const GrayImage image = read_netpbm(write("a.ppm", "P3 2 1 255 255 0 0 0 0 255\n"));
  EXPECT_NEAR(image.at(0, 0), 0.299, 1e-12);
  EXPECT_NEAR(image.at(1, 0), 0.114, 1e-12);
  // and keep their own colours beside.
  EXPECT_EQ(image.rgb, (std::vector<double>{1, 0, 0, 0, 0, 1}));
  EXPECT_TRUE(read_netpbm(write("a.pgm", "P2 2 1 255 255 0\n")).rgb.empty());
}

TEST_F(NetpbmFiles, BadImagesAreIoErrors) {
  auto code = [](const fs::path& file) -> std::optional<ErrorKind> {
    try {
      read_netpbm(file);
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << "message names the file";
      return e.kind();
    }
    return std::nullopt;
  };
  EXPECT_EQ(code(dir_ / "missing.pgm"), ErrorKind::file_unreadable);
  EXPECT_EQ(code(write("png.pgm", "\x89PNG\r\n")), ErrorKind::unknown_format);
  EXPECT_EQ(code(write("short.pgm", "P5\n4 4\n255\nabc")), ErrorKind::file_unreadable);
  EXPECT_EQ(code(write("header.pgm", "P2\n4\n")), ErrorKind::file_unreadable);
  EXPECT_EQ(code(write("range.pgm", "P2 1 1 15 16\n")), ErrorKind::file_unreadable);
  EXPECT_EQ(code(write("zero.pgm", "P2 0 1 15\n")), ErrorKind::file_unreadable);
  EXPECT_EQ(code(write("bits.pbm", "P1 2 1 0 2\n")), ErrorKind::file_unreadable);
}

int mod(int a, int n) { return ((a % n) + n) % n; }

TEST(WeavePattern, FamiliesMatchTheirDefinitions) {
  const WeavePattern plain = parse_weave_pattern("plain");
  ASSERT_EQ(plain.warps, 2);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(plain.over(i, j), (i + j) % 2 == 0);
  const WeavePattern twill = parse_weave_pattern("twill:2/3");
  ASSERT_EQ(twill.warps, 5);
  ASSERT_EQ(twill.wefts, 5);
  for (int j = 0; j < 5; ++j) {
    int over = 0;
    for (int i = 0; i < 5; ++i) {
      EXPECT_EQ(twill.over(i, j), mod(i - j, 5) < 2);
      over += twill.over(i, j);
    }
    EXPECT_EQ(over, 2);
  }
  const WeavePattern satin = parse_weave_pattern("satin:1/7");
  ASSERT_EQ(satin.warps, 8);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) EXPECT_EQ(satin.over(i, j), mod(i - 3 * j, 8) < 1);
  EXPECT_EQ(satin.over(-1, -1), satin.over(7, 7));
}

TEST(WeavePattern, SatinStepsAreCoprimeAndNotAdjacent) {
  EXPECT_EQ(satin_step(5), 2);
  EXPECT_EQ(satin_step(7), 2);
  EXPECT_EQ(satin_step(8), 3);
  EXPECT_EQ(satin_step(3), 0);
  EXPECT_EQ(satin_step(4), 0);
  EXPECT_EQ(satin_step(6), 0);
  for (int n = 5; n <= 16; ++n) {
    const int s = satin_step(n);
    if (s == 0) {
      for (int t = 2; t < n - 1; ++t) EXPECT_NE(std::gcd(t, n), 1) << n;
    } else {
      EXPECT_GT(s, 1);
      EXPECT_LT(s, n - 1);
      EXPECT_EQ(std::gcd(s, n), 1);
    }
  }
}

TEST(WeavePattern, InvalidPatternsAreOptionErrors) {
  for (const std::string spec : {"satin:3/1", "satin:2/2", "satin:1/2", "satin:3/3", "twill:0/3", "twill:2",
                                 "twill:2/3x", "zigzag", "", "satin:40/40"}) {
    try {
      parse_weave_pattern(spec);
      ADD_FAILURE() << spec << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_option) << spec;
      EXPECT_NE(e.text().find("{pattern}"), std::string::npos) << e.what();
    }
  }
  try {
    parse_weave_pattern("/nonexistent/design.pbm");
    ADD_FAILURE() << "missing image accepted";
  } catch (const IoError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::file_unreadable);
  }
}

TEST_F(NetpbmFiles, JacquardImageReadsUprightWithDarkWarpOver) {
  // Image rows top to bottom; weft 0 is the bottom row.
  const fs::path file = write("design.pbm", "P1 3 2\n1 0 0\n0 1 1\n");
  const WeavePattern p = parse_weave_pattern(file.string());
  ASSERT_EQ(p.warps, 3);
  ASSERT_EQ(p.wefts, 2);
  EXPECT_FALSE(p.over(0, 0));
  EXPECT_TRUE(p.over(1, 0));
  EXPECT_TRUE(p.over(2, 0));
  EXPECT_TRUE(p.over(0, 1));
  EXPECT_FALSE(p.over(1, 1));
  EXPECT_FALSE(p.over(2, 1));
}

}  // namespace
}  // namespace meshquilt
