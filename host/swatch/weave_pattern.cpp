#include "swatch/weave_pattern.h"

#include <filesystem>
#include <numeric>
#include <regex>

#include "core/error.h"

namespace meshquilt {
namespace {

constexpr int kMaxEnds = 64;
constexpr int kMaxImageYarns = 1024;

// Messages name the parameters at fault as {name} (OptionError).
[[noreturn]] void invalid(const std::string& message) { throw OptionError("weave: " + message); }
[[noreturn]] void invalid(const std::string& parameter, const std::string& problem) {
  invalid("{" + parameter + "} " + problem);
}

void check_counts(const char* family, int over, int under) {
  if (over < 1 || under < 1 || over + under > kMaxEnds) {
    invalid("pattern", std::string(family) + ":" + std::to_string(over) + "/" + std::to_string(under) +
            " needs 1 <= M, N and M+N <= " + std::to_string(kMaxEnds));
  }
}

WeavePattern shifted_pattern(int over, int under, int step) {
  WeavePattern p;
  p.warps = p.wefts = over + under;
  p.warp_over.resize(static_cast<size_t>(p.warps) * p.wefts);
  for (int j = 0; j < p.wefts; ++j) {
    for (int i = 0; i < p.warps; ++i) {
      p.warp_over[static_cast<size_t>(j) * p.warps + i] = (((i - step * j) % p.warps + p.warps) % p.warps) < over;
    }
  }
  return p;
}

}  // namespace

WeavePattern twill_pattern(int over, int under) {
  check_counts("twill", over, under);
  return shifted_pattern(over, under, 1);
}

int satin_step(int ends) {
  for (int s = 2; s < ends - 1; ++s) {
    if (std::gcd(s, ends) == 1) return s;
  }
  return 0;
}

WeavePattern satin_pattern(int over, int under) {
  check_counts("satin", over, under);
  const int step = satin_step(over + under);
  if (step == 0) {
    invalid("pattern", "satin:" + std::to_string(over) + "/" + std::to_string(under) + " is not a regular satin: no step s with 1 < s < " +
            std::to_string(over + under - 1) + " coprime to " + std::to_string(over + under));
  }
  return shifted_pattern(over, under, step);
}

WeavePattern image_pattern(const GrayImage& image) {
  if (image.width > kMaxImageYarns || image.height > kMaxImageYarns) {
    invalid("pattern", "image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
            ", more than " + std::to_string(kMaxImageYarns) + " yarns a side");
  }
  WeavePattern p;
  p.warps = image.width;
  p.wefts = image.height;
  p.warp_over.resize(static_cast<size_t>(p.warps) * p.wefts);
  for (int j = 0; j < p.wefts; ++j) {
    for (int i = 0; i < p.warps; ++i) {
      p.warp_over[static_cast<size_t>(j) * p.warps + i] = image.at(i, image.height - 1 - j) < 0.5;
    }
  }
  return p;
}

WeavePattern parse_weave_pattern(const std::string& spec) {
  if (spec == "plain") return twill_pattern(1, 1);
  static const std::regex family(R"((twill|satin):(\d{1,4})/(\d{1,4}))");
  std::smatch m;
  if (std::regex_match(spec, m, family)) {
    const int over = std::stoi(m[2].str()), under = std::stoi(m[3].str());
    return m[1] == "twill" ? twill_pattern(over, under) : satin_pattern(over, under);
  }
  const std::filesystem::path path(spec);
  std::string ext = path.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool image_ext = ext == ".pbm" || ext == ".pgm" || ext == ".ppm" || ext == ".pnm";
  if (spec.rfind("twill", 0) == 0 || spec.rfind("satin", 0) == 0 || (!image_ext && !std::filesystem::exists(path))) {
    invalid("pattern", "'" + spec + "' is not plain, twill:M/N, satin:M/N or a PBM/PGM image file");
  }
  return image_pattern(read_netpbm(path));
}

}  // namespace meshquilt
