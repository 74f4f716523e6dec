// The sample reader against images written here (PPM by hand, PNG through our encoder), and
// bilinear, wrapped sampling in closed form, and halving of any size against a sub-cell reference.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "paint/colour_image.h"
#include "render/png_encoding.h"

namespace meshquilt {
namespace {

std::filesystem::path temp(const std::string& name) { return std::filesystem::temp_directory_path() / ("mq_ci_" + name); }

void write(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

TEST(ColourImage, RawAndPlainPpmKeepTheirColours) {
  // 2 x 1: red, then (0, 128, 255).
  write(temp("raw.ppm"), std::string("P6\n# a comment\n2 1\n255\n") + std::string("\xff\x00\x00\x00\x80\xff", 6));
  write(temp("plain.ppm"), "P3\n2 1\n255\n255 0 0  0 128 255\n");
  for (const char* name : {"raw.ppm", "plain.ppm"}) {
    const ColourImage image = read_colour_image(temp(name));
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    EXPECT_EQ(image.at(0, 0), glm::dvec3(1.0, 0.0, 0.0)) << name;
    EXPECT_EQ(image.at(1, 0), glm::dvec3(0.0, 128.0 / 255.0, 1.0)) << name;
  }
}

TEST(ColourImage, PngComesBackAsWritten) {
  RgbImage written;
  written.width = 3;
  written.height = 2;
  for (int i = 0; i < 18; ++i) written.rgb.push_back(static_cast<uint8_t>(i * 14));
  write(temp("image.png"), encode_png(written));
  const ColourImage image = read_colour_image(temp("image.png"));
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      const Rgb8 p = written.pixel(x, y);
      EXPECT_EQ(image.at(x, y), glm::dvec3(p[0], p[1], p[2]) / 255.0);
    }
}

TEST(ColourImage, SamplesBilinearlyBetweenCentresAndWraps) {
  ColourImage image;
  image.width = 2;
  image.height = 1;
  image.rgb = {glm::dvec3(0.0), glm::dvec3(1.0)};
  EXPECT_EQ(image.sample({0.5, 0.5}), glm::dvec3(0.0));   // a pixel's centre
  EXPECT_EQ(image.sample({1.0, 0.5}), glm::dvec3(0.5));   // halfway between the two centres
  EXPECT_EQ(image.sample({1.25, 0.7}), glm::dvec3(0.75));
  EXPECT_EQ(image.sample({2.0, 0.5}), glm::dvec3(0.5));   // past the right border: back to the left pixel
  EXPECT_EQ(image.sample({-1.5, 3.5}), glm::dvec3(0.0));  // whole periods away
}

// The reference: each pixel cut into `out` x `out_h` sub-cells, so that every box edge k * w / out
// falls on a sub-cell edge, and each box the plain mean of the sub-cells it holds.
glm::dvec3 box_mean_by_subcells(const ColourImage& image, int out_w, int out_h, int x, int y) {
  glm::dvec3 sum(0.0);
  long count = 0;
  for (long sy = static_cast<long>(y) * image.height; sy < static_cast<long>(y + 1) * image.height; ++sy)
    for (long sx = static_cast<long>(x) * image.width; sx < static_cast<long>(x + 1) * image.width; ++sx) {
      sum += image.at(static_cast<int>(sx / out_w), static_cast<int>(sy / out_h));
      ++count;
    }
  return sum / static_cast<double>(count);
}

TEST(ColourImage, HalvesAnySizeByBoxMeans) {
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{8, 6}, {63, 47}, {17, 10}, {9, 9}}) {
    ColourImage image;
    image.width = w;
    image.height = h;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) image.rgb.emplace_back(std::sin(1.3 * x + 0.7 * y), (x * 7 + y * 3) % 5 / 4.0, 0.5);
    const ColourImage half = halved(image);
    ASSERT_EQ(half.width, w / 2);
    ASSERT_EQ(half.height, h / 2);
    glm::dvec3 mean(0.0), half_mean(0.0);
    for (const glm::dvec3& c : image.rgb) mean += c / static_cast<double>(image.rgb.size());
    for (const glm::dvec3& c : half.rgb) half_mean += c / static_cast<double>(half.rgb.size());
    EXPECT_NEAR(glm::length(mean - half_mean), 0.0, 1e-12) << w << " x " << h;
    for (int y = 0; y < half.height; ++y)
      for (int x = 0; x < half.width; ++x)
        EXPECT_NEAR(glm::length(half.at(x, y) - box_mean_by_subcells(image, half.width, half.height, x, y)), 0.0, 1e-12)
            << w << " x " << h << " at " << x << ", " << y;
  }
}

TEST(ColourImage, ShrinksToAnySizeByBoxMeansAndNeverGrows) {
  ColourImage image;
  image.width = 63;
  image.height = 47;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) image.rgb.emplace_back(std::cos(0.9 * x - 0.4 * y), (x * y) % 7 / 6.0, 0.25);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{20, 13}, {1, 1}, {63, 47}, {62, 5}}) {
    const ColourImage small = shrunk(image, w, h);
    ASSERT_EQ(small.width, w);
    ASSERT_EQ(small.height, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        EXPECT_NEAR(glm::length(small.at(x, y) - box_mean_by_subcells(image, w, h, x, y)), 0.0, 1e-12)
            << w << " x " << h << " at " << x << ", " << y;
  }
  EXPECT_THROW(shrunk(image, 64, 47), InputError);
  EXPECT_THROW(shrunk(image, 0, 10), InputError);
}

TEST(ColourImage, BadFilesGiveOneLineErrors) {
  write(temp("text.png"), "not an image");
  write(temp("short.ppm"), "P6\n4 4\n255\nxx");
  write(temp("broken.png"), std::string("\x89PNG\r\n\x1a\n", 8) + "garbage");
  EXPECT_THROW(read_colour_image(temp("missing.png")), IoError);
  try {
    read_colour_image(temp("text.png"));
    FAIL();
  } catch (const IoError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unknown_format);
  }
  EXPECT_THROW(read_colour_image(temp("short.ppm")), IoError);
  EXPECT_THROW(read_colour_image(temp("broken.png")), IoError);
}

}  // namespace
}  // namespace meshquilt
