#include "render/element_palette.h"

#include <cmath>
#include <numbers>

#include "mesh/topology.h"

namespace meshquilt {
namespace {

Vec3 hsv_to_rgb(double hue, double saturation, double value) {
  const double h = 6.0 * (hue - std::floor(hue));
  const int sector = static_cast<int>(h) % 6;
  const double f = h - std::floor(h);
  const double p = value * (1.0 - saturation);
  const double q = value * (1.0 - saturation * f);
  const double t = value * (1.0 - saturation * (1.0 - f));
  switch (sector) {
    case 0:
      return {value, t, p};
    case 1:
      return {q, value, p};
    case 2:
      return {p, value, t};
    case 3:
      return {p, q, value};
    case 4:
      return {t, p, value};
    default:
      return {value, p, q};
  }
}

}  // namespace

Vec3 element_color(int32_t id) {
  constexpr double kGoldenTurn = 0.6180339887498949;
  constexpr double kSaturation[3] = {0.62, 0.45, 0.70};
  constexpr double kValue[3] = {0.93, 0.95, 0.80};
  // Negative ids (a foreign file's labels) wrap to large ones rather than indexing out of range.
  const uint32_t k = static_cast<uint32_t>(id);
  const double hue = 0.58 + kGoldenTurn * k;  // starts at a blue, then steps around the wheel
  return hsv_to_rgb(hue, kSaturation[k % 3], kValue[k % 3]);
}

std::vector<int32_t> face_element_ids(const TriMesh& mesh) {
  if (mesh.elements.size() == mesh.num_faces()) return mesh.elements;
  return face_components(mesh);
}

}  // namespace meshquilt
