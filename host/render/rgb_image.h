#pragma once
//! An 8-bit RGB image, the output of the renderer and the input of the PNG encoder.

#include <array>
#include <cstdint>
#include <vector>

namespace meshquilt {

using Rgb8 = std::array<uint8_t, 3>;

//! width x height pixels, rows top to bottom, each row left to right.
//! rgb  #(width * height * 3) bytes, R G B per pixel
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;

  Rgb8 pixel(int x, int y) const {
    const size_t i = (static_cast<size_t>(y) * width + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

}  // namespace meshquilt
