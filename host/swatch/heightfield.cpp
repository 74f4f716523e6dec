#include "swatch/heightfield.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "error.h"

namespace meshquilt {
namespace {

[[noreturn]] void invalid(const std::string& message) {
  throw InputError("heightfield: " + message, ExitCode::invalid_option);
}

}  // namespace

HeightfieldOptions HeightfieldOptions::small() {
  HeightfieldOptions o;
  o.builtin_resolution = 16;
  return o;
}

GrayImage builtin_height_image(int resolution) {
  GrayImage image;
  image.width = image.height = resolution;
  image.values.resize(static_cast<size_t>(resolution) * resolution);
  const double k = 4.0 * std::numbers::pi / (resolution - 1);
  for (int r = 0; r < resolution; ++r) {
    for (int c = 0; c < resolution; ++c) {
      image.values[static_cast<size_t>(r) * resolution + c] = 0.5 + 0.5 * std::sin(k * c) * std::sin(k * r);
    }
  }
  return image;
}

GrayImage downsample_image(const GrayImage& image, int max_side) {
  const int longest = std::max(image.width, image.height);
  if (longest <= max_side) return image;
  GrayImage out;
  out.width = std::max(1, static_cast<int>(std::lround(static_cast<double>(image.width) * max_side / longest)));
  out.height = std::max(1, static_cast<int>(std::lround(static_cast<double>(image.height) * max_side / longest)));
  out.values.resize(static_cast<size_t>(out.width) * out.height);
  for (int r = 0; r < out.height; ++r) {
    const int r0 = r * image.height / out.height, r1 = std::max(r0 + 1, (r + 1) * image.height / out.height);
    for (int c = 0; c < out.width; ++c) {
      const int c0 = c * image.width / out.width, c1 = std::max(c0 + 1, (c + 1) * image.width / out.width);
      double sum = 0.0;
      for (int y = r0; y < r1; ++y) {
        for (int x = c0; x < c1; ++x) sum += image.at(x, y);
      }
      out.values[static_cast<size_t>(r) * out.width + c] = sum / ((r1 - r0) * (c1 - c0));
    }
  }
  return out;
}

TriMesh make_heightfield(const HeightfieldOptions& o) {
  if (o.max_resolution < 2) invalid("--max-resolution must be >= 2");
  if (o.image.values.empty() && (o.builtin_resolution < 2 || o.builtin_resolution > 4096)) {
    invalid("--resolution must lie in 2..4096");
  }
  const GrayImage image =
      downsample_image(o.image.values.empty() ? builtin_height_image(o.builtin_resolution) : o.image, o.max_resolution);
  const int W = image.width, H = image.height;
  if (W < 2 || H < 2) invalid("the image needs at least 2 x 2 pixels (got " + std::to_string(W) + "x" + std::to_string(H) + ")");
  if (!(o.size > 0.0) || !std::isfinite(o.size)) invalid("--size must be positive");
  if (!(o.height >= 0.0) || !std::isfinite(o.height)) invalid("--height must be >= 0");
  if (!o.open && (!(o.base > 0.0) || !std::isfinite(o.base))) invalid("--base must be positive for a closed slab");
  const double spacing = o.size / (std::max(W, H) - 1);
  const double thinnest = spacing * (std::min(W, H) - 1);
  const double thickness = o.height + (o.open ? 0.0 : o.base);
  if (thickness >= thinnest) {
    std::ostringstream m;
    m << "relief thickness " << thickness << " (--height" << (o.open ? "" : " + --base")
      << ") must stay below the shorter side " << thinnest << " so that z is the thinnest axis";
    invalid(m.str());
  }

  TriMesh mesh;
  // Grid column c, grid row g (g = 0 at y = 0, the image's bottom row).
  auto top = [&](int c, int g) { return static_cast<int32_t>(g * W + c); };
  for (int g = 0; g < H; ++g) {
    for (int c = 0; c < W; ++c) mesh.positions.emplace_back(c * spacing, g * spacing, o.height * image.at(c, H - 1 - g));
  }
  for (int g = 0; g + 1 < H; ++g) {
    for (int c = 0; c + 1 < W; ++c) {
      const int32_t a = top(c, g), b = top(c + 1, g), cc = top(c + 1, g + 1), d = top(c, g + 1);
      mesh.triangles.push_back({a, b, cc});
      mesh.triangles.push_back({a, cc, d});
    }
  }
  if (!o.open) {
    const auto bottom_base = static_cast<int32_t>(W * H);
    auto bottom = [&](int c, int g) { return bottom_base + top(c, g); };
    for (int g = 0; g < H; ++g) {
      for (int c = 0; c < W; ++c) mesh.positions.emplace_back(c * spacing, g * spacing, -o.base);
    }
    for (int g = 0; g + 1 < H; ++g) {
      for (int c = 0; c + 1 < W; ++c) {
        const int32_t a = bottom(c, g), b = bottom(c + 1, g), cc = bottom(c + 1, g + 1), d = bottom(c, g + 1);
        mesh.triangles.push_back({a, cc, b});
        mesh.triangles.push_back({a, d, cc});
      }
    }
    // The rim, counter-clockwise seen from +z; each step becomes an outward wall quad.
    std::vector<std::pair<int, int>> rim;
    for (int c = 0; c + 1 < W; ++c) rim.emplace_back(c, 0);
    for (int g = 0; g + 1 < H; ++g) rim.emplace_back(W - 1, g);
    for (int c = W - 1; c > 0; --c) rim.emplace_back(c, H - 1);
    for (int g = H - 1; g > 0; --g) rim.emplace_back(0, g);
    for (size_t k = 0; k < rim.size(); ++k) {
      const auto [c0, g0] = rim[k];
      const auto [c1, g1] = rim[(k + 1) % rim.size()];
      mesh.triangles.push_back({top(c0, g0), bottom(c0, g0), bottom(c1, g1)});
      mesh.triangles.push_back({top(c0, g0), bottom(c1, g1), top(c1, g1)});
    }
  }
  mesh.elements.assign(mesh.triangles.size(), 0);
  return mesh;
}

}  // namespace meshquilt
