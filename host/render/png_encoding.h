#pragma once
//! PNG encoding of an RGB image, through libpng.

#include <string>

#include "render/rgb_image.h"

namespace meshquilt {

//! The bytes of an 8-bit RGB PNG file holding `image` (libpng's simplified API, default zlib
//! compression), ready to be written to a file in one piece.
//! \pre image.rgb.size() == width * height * 3, width and height >= 1.
//! \throw InputError(invalid_option) for an image of another size; IoError(write_failed) when libpng fails.
std::string encode_png(const RgbImage& image);

}  // namespace meshquilt
