#include "render/png_encoding.h"

#include <png.h>

#include <cstring>

#include "core/error.h"

namespace meshquilt {

std::string encode_png(const RgbImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
    throw InputError("png: image of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                         " pixels holds " + std::to_string(image.rgb.size()) + " bytes",
                     ErrorKind::invalid_option);
  // The simplified API reports errors through its return value and `message`, so no setjmp
  // crosses C++ frames.
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  // First call measures, second writes.
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0, nullptr))
    throw IoError(ErrorKind::write_failed, std::string("PNG encoding: ") + png.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr))
    throw IoError(ErrorKind::write_failed, std::string("PNG encoding: ") + png.message);
  bytes.resize(size);
  png_image_free(&png);
  return bytes;
}

}  // namespace meshquilt
