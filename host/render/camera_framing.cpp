#include "render/camera_framing.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace meshquilt {
namespace {

// The world direction that shows as "up" in the image: +z, except when looking along z.
Vec3 world_up(View view) { return view == View::top ? Vec3(0, 1, 0) : Vec3(0, 0, 1); }

}  // namespace

Vec3 view_direction(View view) {
  switch (view) {
    case View::top:
      return {0, 0, -1};
    case View::front:
      return {0, 1, 0};
    case View::side:
      return {-1, 0, 0};
    case View::oblique:
      break;
  }
  // The camera sits at azimuth -45 degrees (between +x and -y), above the plane.
  const double elevation = kObliqueElevationDegrees * std::numbers::pi / 180.0;
  const double azimuth = -0.25 * std::numbers::pi;
  const Vec3 to_camera(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                       std::sin(elevation));
  return -to_camera;
}

namespace {

OrthographicCamera frame(const Vec3& lo, const Vec3& hi, const Vec3& forward, const Vec3& world_up, int width,
                         int height, double margin) {
  OrthographicCamera camera;
  camera.width = width;
  camera.height = height;
  camera.forward = forward;
  camera.right = glm::normalize(glm::cross(camera.forward, world_up));
  camera.up = glm::cross(camera.right, camera.forward);
  // A box projects symmetrically about its centre, so the centre is the image centre.
  camera.center = 0.5 * (lo + hi);
  double extent_x = 0.0, extent_y = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
    extent_x = std::max(extent_x, 2.0 * std::abs(glm::dot(p - camera.center, camera.right)));
    extent_y = std::max(extent_y, 2.0 * std::abs(glm::dot(p - camera.center, camera.up)));
  }
  const double usable = 1.0 - 2.0 * margin;
  camera.pixel_size = std::max(extent_x / (width * usable), extent_y / (height * usable));
  if (!(camera.pixel_size > 0.0)) camera.pixel_size = 1.0;
  // Every point of the box lies within half its diagonal of the centre; starting a full diagonal
  // back keeps the ray origins in front of it, with room for rounding.
  camera.depth = std::max(glm::length(hi - lo), 1.0 * camera.pixel_size);
  return camera;
}

}  // namespace

OrthographicCamera frame_box(const Vec3& lo, const Vec3& hi, View view, int width, int height, double margin) {
  return frame(lo, hi, view_direction(view), world_up(view), width, height, margin);
}

OrthographicCamera frame_box_along(const Vec3& lo, const Vec3& hi, const Vec3& forward, int width, int height,
                                   double margin) {
  const bool vertical = std::abs(forward.z) > std::cos(std::numbers::pi / 180.0);
  return frame(lo, hi, forward, vertical ? Vec3(0, 1, 0) : Vec3(0, 0, 1), width, height, margin);
}

}  // namespace meshquilt
