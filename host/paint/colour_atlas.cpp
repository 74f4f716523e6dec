#include "paint/colour_atlas.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include <glm/common.hpp>

#include "core/error.h"
#include "shell/texture_atlas.h"
#include "surface/surface_types.h"

namespace meshquilt {
namespace {

constexpr int kGutter = 2;

struct Box {
  glm::dvec2 lo{1e300}, hi{-1e300};
};

// Shelf packing at `scale` texels per unit, tallest charts first: each chart's texel origin, or
// nothing when they overflow the image.
bool pack(const std::vector<Box>& boxes, double scale, int size, std::vector<glm::dvec2>& origin) {
  std::vector<size_t> order(boxes.size());
  std::iota(order.begin(), order.end(), size_t{0});
  const auto extent = [&](size_t c) { return glm::ceil((boxes[c].hi - boxes[c].lo) * scale) + 2.0 * kGutter + 1.0; };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return extent(a).y > extent(b).y; });
  origin.assign(boxes.size(), glm::dvec2(0.0));
  double x = 0.0, y = 0.0, row = 0.0;
  for (size_t c : order) {
    const glm::dvec2 e = extent(c);
    if (e.x > size) return false;
    if (x + e.x > size) {
      x = 0.0;
      y += row;
      row = 0.0;
    }
    if (y + e.y > size) return false;
    origin[c] = {x + kGutter, y + kGutter};
    x += e.x;
    row = std::max(row, e.y);
  }
  return true;
}

// Colour at texel centres inside triangle (p0, p1, p2) (texel units), blended from its corners.
void draw(RgbImage& image, std::vector<uint8_t>& covered, const std::array<glm::dvec2, 3>& p,
          const std::array<std::array<uint8_t, 3>, 3>& colour) {
  const glm::dvec2 lo = glm::min(p[0], glm::min(p[1], p[2])), hi = glm::max(p[0], glm::max(p[1], p[2]));
  const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  if (std::abs(area) < 1e-18) return;
  const int x0 = std::max(0, static_cast<int>(std::floor(lo.x - 0.5))), x1 = std::min(image.width - 1, static_cast<int>(std::ceil(hi.x)));
  const int y0 = std::max(0, static_cast<int>(std::floor(lo.y - 0.5))), y1 = std::min(image.height - 1, static_cast<int>(std::ceil(hi.y)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::dvec2 q(x + 0.5, y + 0.5);
      const double b1 = ((q.x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (q.y - p[0].y)) / area;
      const double b2 = ((p[1].x - p[0].x) * (q.y - p[0].y) - (q.x - p[0].x) * (p[1].y - p[0].y)) / area;
      const double b0 = 1.0 - b1 - b2;
      constexpr double kSlack = -1e-9;
      if (b0 < kSlack || b1 < kSlack || b2 < kSlack) continue;
      const size_t i = static_cast<size_t>(y) * image.width + x;
      for (int k = 0; k < 3; ++k)
        image.rgb[3 * i + k] = static_cast<uint8_t>(std::lround(b0 * colour[0][k] + b1 * colour[1][k] + b2 * colour[2][k]));
      covered[i] = 1;
    }
}

// The refined faces of one base face, in split_faces' order: its corners in texels, split as
// split_faces splits positions (faces f x 4^levels onwards).
void draw_split(RgbImage& image, std::vector<uint8_t>& covered, const TriMesh& refined, size_t& face,
                const std::array<glm::dvec2, 3>& p, int levels) {
  if (levels == 0) {
    const Tri& t = refined.triangles[face++];
    draw(image, covered, p, {refined.colors[t[0]], refined.colors[t[1]], refined.colors[t[2]]});
    return;
  }
  const glm::dvec2 ab = 0.5 * (p[0] + p[1]), bc = 0.5 * (p[1] + p[2]), ca = 0.5 * (p[2] + p[0]);
  draw_split(image, covered, refined, face, {p[0], ab, ca}, levels - 1);
  draw_split(image, covered, refined, face, {ab, p[1], bc}, levels - 1);
  draw_split(image, covered, refined, face, {ca, bc, p[2]}, levels - 1);
  draw_split(image, covered, refined, face, {ab, bc, ca}, levels - 1);
}

// Texels no face covered take the mean of covered neighbours, ring by ring, over the gutter.
void fill_gutters(RgbImage& image, std::vector<uint8_t>& covered) {
  for (int ring = 0; ring < 2 * kGutter; ++ring) {
    std::vector<uint8_t> next = covered;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const size_t i = static_cast<size_t>(y) * image.width + x;
        if (covered[i]) continue;
        int sum[3] = {0, 0, 0}, n = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= image.width || v >= image.height) continue;
            const size_t j = static_cast<size_t>(v) * image.width + u;
            if (!covered[j]) continue;
            for (int k = 0; k < 3; ++k) sum[k] += image.rgb[3 * j + k];
            ++n;
          }
        if (n == 0) continue;
        for (int k = 0; k < 3; ++k) image.rgb[3 * i + k] = static_cast<uint8_t>((sum[k] + n / 2) / n);
        next[i] = 1;
      }
    covered = std::move(next);
  }
}

}  // namespace

ColourAtlas bake_colour_atlas(const TriMesh& base, const TriMesh& refined, int levels, int size) {
  if (size < 16 || size > 16384)
    throw InputError("{atlas}: expected 16..16384 texels a side, got " + std::to_string(size), ErrorKind::invalid_option);
  const double parts = std::pow(4.0, levels);
  if (levels < 0 || static_cast<double>(refined.num_faces()) != static_cast<double>(base.num_faces()) * parts ||
      refined.colors.size() != refined.num_vertices())
    throw InputError("{atlas}: the coloured mesh is not the base split " + std::to_string(levels) + " times",
                     ErrorKind::invalid_option);
  const TextureAtlas atlas = build_texture_atlas(BaseSurface(base));
  std::vector<Box> boxes(atlas.charts);
  double area = 0.0;
  for (size_t a = 0; a < atlas.uv.size(); ++a) {
    Box& box = boxes[atlas.vertex_chart[a]];
    box.lo = glm::min(box.lo, atlas.uv[a]);
    box.hi = glm::max(box.hi, atlas.uv[a]);
  }
  for (const Box& box : boxes) area += (box.hi.x - box.lo.x) * (box.hi.y - box.lo.y);
  // Start where the boxes would fill the image, and shrink until they fit.
  double scale = std::sqrt(static_cast<double>(size) * size / std::max(area, 1e-300));
  std::vector<glm::dvec2> origin;
  int tries = 0;
  while (!pack(boxes, scale, size, origin)) {
    scale *= 0.97;
    if (++tries > 400 || scale * std::sqrt(area / std::max(1, atlas.charts)) < 1.0)
      throw InputError("{atlas}: " + std::to_string(atlas.charts) + " charts do not fit " + std::to_string(size) + " x " +
                           std::to_string(size) + " texels: use a larger atlas",
                       ErrorKind::invalid_option);
  }
  ColourAtlas out;
  out.charts = atlas.charts;
  out.texels_per_unit = scale;
  out.image.width = out.image.height = size;
  out.image.rgb.assign(static_cast<size_t>(size) * size * 3, 0);
  std::vector<uint8_t> covered(static_cast<size_t>(size) * size, 0);
  const auto texel = [&](int32_t a) { return origin[atlas.vertex_chart[a]] + (atlas.uv[a] - boxes[atlas.vertex_chart[a]].lo) * scale; };
  out.face_uv.resize(base.num_faces());
  size_t face = 0;
  for (size_t f = 0; f < base.num_faces(); ++f) {
    std::array<glm::dvec2, 3> p;
    for (int k = 0; k < 3; ++k) {
      p[k] = texel(atlas.corners[f][k]);
      out.face_uv[f][k] = glm::vec2(p[k] / static_cast<double>(size));
    }
    draw_split(out.image, covered, refined, face, p, levels);
  }
  fill_gutters(out.image, covered);
  return out;
}

}  // namespace meshquilt
