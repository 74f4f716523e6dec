#include "paint/colour_image.h"

#include <png.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "swatch/netpbm.h"

namespace meshquilt {
namespace {

int wrapped(int i, int n) { return ((i % n) + n) % n; }

ColourImage read_png(const std::string& bytes, const std::string& name) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()))
    throw IoError(ErrorKind::file_unreadable, name + ": not a readable PNG (" + png.message + ")");
  png.format = PNG_FORMAT_RGB;
  std::vector<uint8_t> pixels(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw IoError(ErrorKind::file_unreadable, name + ": corrupt PNG (" + message + ")");
  }
  ColourImage image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(static_cast<size_t>(image.width) * image.height);
  for (size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = glm::dvec3(pixels[3 * i], pixels[3 * i + 1], pixels[3 * i + 2]) / 255.0;
  return image;
}

// Netpbm: a raw or plain PPM keeps its colour; other kinds arrive grey through read_netpbm.
ColourImage read_ppm(const std::string& bytes, const std::string& name) {
  if (bytes.compare(0, 2, "P6") != 0 && bytes.compare(0, 2, "P3") != 0) {
    const GrayImage grey = parse_netpbm(bytes, name);
    ColourImage image;
    image.width = grey.width;
    image.height = grey.height;
    for (double v : grey.values) image.rgb.emplace_back(v);
    return image;
  }
  // The header: magic, width, height, maxval, with '#' comments; then one whitespace byte (raw).
  size_t at = 2;
  const auto next_number = [&]() -> long {
    while (at < bytes.size()) {
      if (bytes[at] == '#') {
        while (at < bytes.size() && bytes[at] != '\n') ++at;
      } else if (std::isspace(static_cast<unsigned char>(bytes[at]))) {
        ++at;
      } else {
        break;
      }
    }
    size_t start = at;
    while (at < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[at]))) ++at;
    if (start == at || at - start > 9) throw IoError(ErrorKind::file_unreadable, name + ": corrupt PPM header");
    return std::stol(bytes.substr(start, at - start));
  };
  const long width = next_number(), height = next_number(), maxval = next_number();
  if (width < 1 || height < 1 || maxval < 1 || maxval > 65535 || width * height > (1L << 26))
    throw IoError(ErrorKind::file_unreadable, name + ": PPM of " + std::to_string(width) + " x " + std::to_string(height) + " pixels, maxval " +
                      std::to_string(maxval) + " is not supported");
  ColourImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  const size_t count = static_cast<size_t>(width) * height * 3;
  std::vector<double> values;
  values.reserve(count);
  if (bytes[1] == '6') {
    ++at;  // the single whitespace byte after maxval
    const size_t size = maxval < 256 ? 1 : 2;
    if (bytes.size() < at + count * size)
      throw IoError(ErrorKind::file_unreadable, name + ": PPM pixels are truncated");
    for (size_t i = 0; i < count; ++i) {
      const auto byte = [&](size_t k) { return static_cast<unsigned char>(bytes[at + k]); };
      values.push_back(size == 1 ? byte(i) : byte(2 * i) * 256.0 + byte(2 * i + 1));
    }
  } else {
    for (size_t i = 0; i < count; ++i) values.push_back(static_cast<double>(next_number()));
  }
  for (size_t i = 0; i < count / 3; ++i)
    image.rgb.emplace_back(glm::dvec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]) / static_cast<double>(maxval));
  return image;
}

}  // namespace

glm::dvec3 ColourImage::sample(const glm::dvec2& p) const {
  const double x = p.x - 0.5, y = p.y - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  const int x0 = wrapped(static_cast<int>(fx), width), y0 = wrapped(static_cast<int>(fy), height);
  const int x1 = wrapped(x0 + 1, width), y1 = wrapped(y0 + 1, height);
  return (1.0 - ty) * ((1.0 - tx) * at(x0, y0) + tx * at(x1, y0)) + ty * ((1.0 - tx) * at(x0, y1) + tx * at(x1, y1));
}

ColourImage read_colour_image(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(ErrorKind::file_unreadable, file.string() + ": cannot be read");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return read_png(bytes, file.string());
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6') return read_ppm(bytes, file.string());
  throw IoError(ErrorKind::unknown_format, file.string() + ": not a PNG or Netpbm image");
}

}  // namespace meshquilt
