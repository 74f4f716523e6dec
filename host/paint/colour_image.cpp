#include "paint/colour_image.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <utility>

#include "core/error.h"
#include "swatch/netpbm.h"

namespace meshquilt {
namespace {

// Divisions only off the image: the painter reads mostly inside it.
int wrapped(int i, int n) { return i >= 0 && i < n ? i : ((i % n) + n) % n; }

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

// Netpbm through the swatch library's reader: a PPM keeps its colours, PGM and PBM are grey.
ColourImage read_netpbm_colour(std::string bytes, const std::string& name) {
  const GrayImage netpbm = parse_netpbm(std::move(bytes), name);
  ColourImage image;
  image.width = netpbm.width;
  image.height = netpbm.height;
  for (size_t i = 0; i < netpbm.values.size(); ++i)
    image.rgb.push_back(netpbm.rgb.empty() ? glm::dvec3(netpbm.values[i])
                                           : glm::dvec3(netpbm.rgb[3 * i], netpbm.rgb[3 * i + 1], netpbm.rgb[3 * i + 2]));
  return image;
}

}  // namespace

glm::dvec3 ColourImage::sample(const glm::dvec2& p) const {
  const double x = p.x - 0.5, y = p.y - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  const int x0 = wrapped(static_cast<int>(fx), width), y0 = wrapped(static_cast<int>(fy), height);
  const int x1 = x0 + 1 == width ? 0 : x0 + 1, y1 = y0 + 1 == height ? 0 : y0 + 1;
  return (1.0 - ty) * ((1.0 - tx) * at(x0, y0) + tx * at(x1, y0)) + ty * ((1.0 - tx) * at(x0, y1) + tx * at(x1, y1));
}

ColourImage read_colour_image(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(ErrorKind::file_unreadable, file.string() + ": cannot be read");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return read_png(bytes, file.string());
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6') return read_netpbm_colour(bytes, file.string());
  throw IoError(ErrorKind::unknown_format, file.string() + ": not a PNG or Netpbm image");
}

namespace {

// Each output cell's mean over [k * factor, (k + 1) * factor) of a wrapped row of `size` cells,
// as (first cell, weights): a box filter for any factor.
struct BoxWeights {
  std::vector<int> first;
  std::vector<std::vector<double>> weights;
};

BoxWeights box_weights(int size, int out) {
  const double factor = static_cast<double>(size) / out;
  BoxWeights box;
  for (int k = 0; k < out; ++k) {
    const double a = k * factor, b = (k + 1) * factor;
    const int first = static_cast<int>(std::floor(a));
    std::vector<double> w;
    for (int i = first; i < b; ++i) w.push_back((std::min<double>(i + 1, b) - std::max<double>(i, a)) / factor);
    box.first.push_back(first);
    box.weights.push_back(std::move(w));
  }
  return box;
}

}  // namespace

ColourImage halved(const ColourImage& image) {
  if (image.width % 2 != 0 || image.height % 2 != 0) return shrunk(image, image.width / 2, image.height / 2);
  ColourImage out;
  out.width = image.width / 2;
  out.height = image.height / 2;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      out.rgb.push_back(0.25 * (image.at(2 * x, 2 * y) + image.at(2 * x + 1, 2 * y) + image.at(2 * x, 2 * y + 1) +
                                image.at(2 * x + 1, 2 * y + 1)));
  return out;
}

ColourImage shrunk(const ColourImage& image, int width, int height) {
  if (width < 1 || height < 1 || width > image.width || height > image.height)
    throw InputError("{sample_width}: the image can only shrink, to at least a pixel (" + std::to_string(image.width) +
                         " x " + std::to_string(image.height) + " to " + std::to_string(width) + " x " +
                         std::to_string(height) + ")",
                     ErrorKind::invalid_option);
  ColourImage out;
  out.width = width;
  out.height = height;
  const BoxWeights bx = box_weights(image.width, out.width), by = box_weights(image.height, out.height);
  std::vector<glm::dvec3> rows(static_cast<size_t>(out.width) * image.height, glm::dvec3(0.0));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (size_t i = 0; i < bx.weights[x].size(); ++i)
        rows[static_cast<size_t>(y) * out.width + x] +=
            bx.weights[x][i] * image.at((bx.first[x] + static_cast<int>(i)) % image.width, y);
  out.rgb.assign(static_cast<size_t>(out.width) * out.height, glm::dvec3(0.0));
  for (int y = 0; y < out.height; ++y)
    for (size_t i = 0; i < by.weights[y].size(); ++i) {
      const int row = (by.first[y] + static_cast<int>(i)) % image.height;
      for (int x = 0; x < out.width; ++x)
        out.rgb[static_cast<size_t>(y) * out.width + x] += by.weights[y][i] * rows[static_cast<size_t>(row) * out.width + x];
    }
  return out;
}

ColourImage shrunk_to_width(const ColourImage& image, int width) {
  const double height = static_cast<double>(image.height) * width / std::max(image.width, 1);
  return shrunk(image, width, std::max(1, static_cast<int>(std::lround(height))));
}

}  // namespace meshquilt
