#include "swatch/heightfield.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.h"

namespace meshquilt {
namespace {

// Messages name the parameters at fault as {name} (OptionError).
[[noreturn]] void invalid(const std::string& message) { throw OptionError("heightfield: " + message); }
[[noreturn]] void invalid(const std::string& parameter, const std::string& problem) {
  invalid("{" + parameter + "} " + problem);
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
  if (o.max_resolution < 2) invalid("max_resolution", "must be >= 2");
  if (o.image.values.empty() && (o.builtin_resolution < 2 || o.builtin_resolution > 4096)) {
    invalid("resolution", "must lie in 2..4096");
  }
  const GrayImage image =
      downsample_image(o.image.values.empty() ? builtin_height_image(o.builtin_resolution) : o.image, o.max_resolution);
  const int W = image.width, H = image.height;
  if (W < 2 || H < 2) invalid("the image needs at least 2 x 2 pixels (got " + std::to_string(W) + "x" + std::to_string(H) + ")");
  if (!(o.size > 0.0) || !std::isfinite(o.size)) invalid("size", "must be positive");
  if (!(o.height >= 0.0) || !std::isfinite(o.height)) invalid("height", "must be >= 0");
  if (!o.open && (!(o.base > 0.0) || !std::isfinite(o.base))) invalid("base", "must be positive for a closed slab");
  const double spacing = o.size / (std::max(W, H) - 1);
  const double thinnest = spacing * (std::min(W, H) - 1);
  const double thickness = o.height + (o.open ? 0.0 : o.base);
  if (thickness >= thinnest) {
    std::ostringstream m;
    m << "relief thickness " << thickness << " ({height}" << (o.open ? "" : " + {base}")
      << ") must stay below the shorter side " << thinnest << " so that z is the thinnest axis";
    invalid(m.str());
  }

  if (o.tiles < 1) invalid("tiles", "must be >= 1");
  const int stride_x = W / o.tiles, stride_y = H / o.tiles;
  if (o.tiles > 1 && (stride_x < 3 || stride_y < 3)) {
    invalid(std::to_string(o.tiles) + " tiles a side leave fewer than 3 pixels per tile of a " + std::to_string(W) +
            "x" + std::to_string(H) + " image");
  }

  TriMesh mesh;
  // One element over grid columns [c0, c1] x rows [g0, g1] (g = 0 at y = 0, the image's bottom
  // row): the top grid, and for a closed slab the bottom grid and the walls between them.
  const auto add_piece = [&](int c0, int c1, int g0, int g1, int32_t element) {
    const int w = c1 - c0 + 1, h = g1 - g0 + 1;
    const auto first = static_cast<int32_t>(mesh.positions.size());
    auto top = [&](int c, int g) { return first + static_cast<int32_t>(g * w + c); };
    for (int g = 0; g < h; ++g) {
      for (int c = 0; c < w; ++c)
        mesh.positions.emplace_back((c0 + c) * spacing, (g0 + g) * spacing, o.height * image.at(c0 + c, H - 1 - (g0 + g)));
    }
    for (int g = 0; g + 1 < h; ++g) {
      for (int c = 0; c + 1 < w; ++c) {
        const int32_t a = top(c, g), b = top(c + 1, g), cc = top(c + 1, g + 1), d = top(c, g + 1);
        mesh.triangles.push_back({a, b, cc});
        mesh.triangles.push_back({a, cc, d});
      }
    }
    if (!o.open) {
      const auto bottom_base = static_cast<int32_t>(w * h);
      auto bottom = [&](int c, int g) { return bottom_base + top(c, g); };
      for (int g = 0; g < h; ++g) {
        for (int c = 0; c < w; ++c) mesh.positions.emplace_back((c0 + c) * spacing, (g0 + g) * spacing, -o.base);
      }
      for (int g = 0; g + 1 < h; ++g) {
        for (int c = 0; c + 1 < w; ++c) {
          const int32_t a = bottom(c, g), b = bottom(c + 1, g), cc = bottom(c + 1, g + 1), d = bottom(c, g + 1);
          mesh.triangles.push_back({a, cc, b});
          mesh.triangles.push_back({a, d, cc});
        }
      }
      // The rim, counter-clockwise seen from +z; each step becomes an outward wall quad.
      std::vector<std::pair<int, int>> rim;
      for (int c = 0; c + 1 < w; ++c) rim.emplace_back(c, 0);
      for (int g = 0; g + 1 < h; ++g) rim.emplace_back(w - 1, g);
      for (int c = w - 1; c > 0; --c) rim.emplace_back(c, h - 1);
      for (int g = h - 1; g > 0; --g) rim.emplace_back(0, g);
      for (size_t k = 0; k < rim.size(); ++k) {
        const auto [x0, y0] = rim[k];
        const auto [x1, y1] = rim[(k + 1) % rim.size()];
        mesh.triangles.push_back({top(x0, y0), bottom(x0, y0), bottom(x1, y1)});
        mesh.triangles.push_back({top(x0, y0), bottom(x1, y1), top(x1, y1)});
      }
    }
    mesh.elements.resize(mesh.triangles.size(), element);
  };
  if (o.tiles == 1) {
    add_piece(0, W - 1, 0, H - 1, 0);
  } else {
    // Tiles of stride - 1 pixel spacings with one spacing of grout between them.
    for (int ty = 0; ty < o.tiles; ++ty)
      for (int tx = 0; tx < o.tiles; ++tx)
        add_piece(tx * stride_x, (tx + 1) * stride_x - 1, ty * stride_y, (ty + 1) * stride_y - 1, ty * o.tiles + tx);
  }
  return mesh;
}

}  // namespace meshquilt
