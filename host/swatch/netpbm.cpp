#include "swatch/netpbm.h"

#include <cctype>
#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"

namespace meshquilt {
namespace {

class Reader {
 public:
  Reader(std::string bytes, std::string name) : bytes_(std::move(bytes)), name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw IoError(ErrorKind::file_unreadable, name_ + ": " + problem);
  }

  // Whitespace and comments may separate any two header tokens.
  void skip_space() {
    while (pos_ < bytes_.size()) {
      const char c = bytes_[pos_];
      if (c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        return;
      }
    }
  }

  long number(const char* what, long lo, long hi) {
    skip_space();
    long value = 0;
    size_t digits = 0;
    while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_]))) {
      value = value * 10 + (bytes_[pos_++] - '0');
      if (value > hi) fail(std::string(what) + " out of range");
      ++digits;
    }
    if (digits == 0) fail(std::string("truncated or corrupt ") + what);
    if (value < lo) fail(std::string(what) + " out of range");
    return value;
  }

  // Plain PBM allows bits without separating whitespace ("0110").
  int bit() {
    skip_space();
    if (pos_ >= bytes_.size() || (bytes_[pos_] != '0' && bytes_[pos_] != '1')) fail("truncated or corrupt bitmap data");
    return bytes_[pos_++] - '0';
  }

  // Raw formats: exactly one whitespace byte after the header.
  void end_header() {
    if (pos_ >= bytes_.size() || !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) fail("corrupt header");
    ++pos_;
  }

  unsigned byte() {
    if (pos_ >= bytes_.size()) fail("truncated image data");
    return static_cast<unsigned char>(bytes_[pos_++]);
  }

  void skip(size_t n) { pos_ += n; }

  size_t remaining() const { return bytes_.size() - pos_; }

 private:
  std::string bytes_;
  std::string name_;
  size_t pos_ = 0;
};

}  // namespace

GrayImage read_netpbm(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(ErrorKind::file_unreadable, name + ": cannot open image");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw IoError(ErrorKind::file_unreadable, name + ": read error");
  return parse_netpbm(std::move(bytes), name);
}

GrayImage parse_netpbm(std::string bytes, const std::string& name) {
  if (bytes.size() < 2 || bytes[0] != 'P' || bytes[1] < '1' || bytes[1] > '6') {
    throw IoError(ErrorKind::unknown_format, name + ": not a PBM/PGM/PPM image (no P1..P6 magic number)");
  }
  const int kind = bytes[1] - '0';
  Reader reader(std::move(bytes), name);
  reader.skip(2);
  GrayImage image;
  image.width = static_cast<int>(reader.number("width", 1, 1 << 15));
  image.height = static_cast<int>(reader.number("height", 1, 1 << 15));
  const bool bitmap = kind == 1 || kind == 4;
  const bool color = kind == 3 || kind == 6;
  const long maxval = bitmap ? 1 : reader.number("maxval", 1, 65535);
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  const int channels = color ? 3 : 1;
  // Honest sizes: the header may declare 32768 x 32768 pixels in a few bytes. Each sample takes
  // at least 1 character in plain PBM ("01"), 2 in other plain forms ("0 "), its bytes in raw
  // forms (the last plain sample may lack its separator); refuse before allocating 8 bytes a pixel.
  {
    const size_t samples = pixels * channels;
    const size_t sample_bytes = kind == 1 ? 1 : kind <= 3 ? 2 : maxval > 255 ? 2 : 1;
    const size_t needed = kind == 4 ? (static_cast<size_t>(image.width) + 7) / 8 * image.height
                                    : samples * sample_bytes - (kind <= 3 && kind != 1 ? 1 : 0);
    if (reader.remaining() < needed) {
      reader.fail("header declares " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                  " pixels, more than the " + std::to_string(reader.remaining()) + " bytes after it hold (truncated?)");
    }
  }
  image.values.resize(pixels);
  auto sample = [&](bool raw) -> double {
    if (!raw) return static_cast<double>(reader.number("sample", 0, maxval));
    unsigned v = reader.byte();
    if (maxval > 255) v = (v << 8) | reader.byte();
    if (v > static_cast<unsigned>(maxval)) reader.fail("sample exceeds maxval");
    return v;
  };
  if (kind == 1) {
    for (auto& v : image.values) v = 1.0 - reader.bit();
  } else if (kind == 4) {
    reader.end_header();
    const size_t row_bytes = (static_cast<size_t>(image.width) + 7) / 8;
    if (reader.remaining() < row_bytes * image.height) reader.fail("truncated image data");
    for (int r = 0; r < image.height; ++r) {
      unsigned current = 0;
      for (int c = 0; c < image.width; ++c) {
        if (c % 8 == 0) current = reader.byte();
        image.values[static_cast<size_t>(r) * image.width + c] = ((current >> (7 - c % 8)) & 1u) ? 0.0 : 1.0;
      }
    }
  } else {
    const bool raw = kind >= 5;
    if (raw) reader.end_header();
    if (color) image.rgb.reserve(3 * pixels);
    for (auto& v : image.values) {
      if (channels == 1) {
        v = sample(raw) / maxval;
      } else {
        const double r = sample(raw), g = sample(raw), b = sample(raw);
        v = (0.299 * r + 0.587 * g + 0.114 * b) / maxval;
        image.rgb.insert(image.rgb.end(), {r / maxval, g / maxval, b / maxval});
      }
    }
  }
  return image;
}

}  // namespace meshquilt
