#pragma once
//! An RGB image sample for synthesis on surfaces: colours in [0, 1], read from PNG or Netpbm,
//! sampled between pixel centres and wrapped round its borders (a sample is a tile of texture).

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace meshquilt {

//! width x height pixels, rows top to bottom; pixel (x, y) is centred at (x + 0.5, y + 0.5).
struct ColourImage {
  int width = 0;
  int height = 0;
  std::vector<glm::dvec3> rgb;  //!< #(width * height), row-major

  const glm::dvec3& at(int x, int y) const { return rgb[static_cast<size_t>(y) * width + x]; }
  //! Bilinear between pixel centres at the continuous position p (pixels), wrapping round.
  glm::dvec3 sample(const glm::dvec2& p) const;
};

//! The grey a colour reads as (Rec. 601 luma): what relief raises, and what its sample is
//! written as.
inline double luma(const glm::dvec3& rgb) { return 0.299 * rgb.r + 0.587 * rgb.g + 0.114 * rgb.b; }

//! The image at half its size: each pixel the mean of a 2 x 2 block where both sides are even;
//! otherwise shrunk to half each side rounded down (63 to 31).
ColourImage halved(const ColourImage& image);

//! The image shrunk to width x height: each pixel the mean over its box of the image taken as
//! constant pixels (a box filter, which keeps the image's mean).
//! \throw InputError(invalid_option) naming {sample_width} for a size under 1 or over the image's.
ColourImage shrunk(const ColourImage& image, int width, int height);

//! shrunk to `width` pixels across, the height rounded to keep the aspect (at least a pixel):
//! `--sample-width`.
ColourImage shrunk_to_width(const ColourImage& image, int width);

//! Reads a PNG (any colour type, through libpng; alpha dropped) or a Netpbm file (PPM in
//! colour, PGM and PBM as grey).
//! \throw IoError(file_unreadable) "FILE: problem" for a missing, unreadable or corrupt file;
//!        IoError(unknown_format) for another format.
ColourImage read_colour_image(const std::filesystem::path& file);

}  // namespace meshquilt
