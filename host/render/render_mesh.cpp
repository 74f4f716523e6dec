#include "render/render_mesh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <string>
#include <unordered_set>

#include "core/error.h"
#include "render/element_palette.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {

// Material of shaded mode, and how much of the element's colour tints it.
const Vec3 kNeutral(0.74, 0.77, 0.82);
constexpr double kShadedTint = 0.22;

// Light: ambient + key (from the upper left, behind the camera) + headlight. The weights sum to
// about 1 for a face turned to both lights; the darkest lit face keeps the ambient share.
constexpr double kAmbient = 0.28;
constexpr double kKey = 0.52;
constexpr double kHead = 0.26;

struct Lights {
  Vec3 key;   // unit vector towards the key light
  Vec3 head;  // unit vector towards the camera
};

Lights lights_for(const OrthographicCamera& camera) {
  return {glm::normalize(-camera.forward + 0.7 * camera.up - 0.45 * camera.right), -camera.forward};
}

// Unit normal of each face, or zero for a degenerate one (it is never hit: ray_triangle's
// determinant vanishes).
std::vector<Vec3> face_normals(const TriMesh& mesh) {
  std::vector<Vec3> normals(mesh.num_faces(), Vec3(0.0));
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    const Vec3 n =
        glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    const double length = glm::length(n);
    if (length > 0.0) normals[f] = n / length;
  }
  return normals;
}

// Base colour of each face for the mode.
std::vector<Vec3> face_colors(const TriMesh& mesh, RenderMode mode, int32_t plain_element) {
  const std::vector<int32_t> ids = face_element_ids(mesh);
  std::vector<Vec3> colors(mesh.num_faces());
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (plain_element >= 0 && ids[f] == plain_element) {
      colors[f] = Vec3(0.72);
      continue;
    }
    if (mode == RenderMode::colors) {
      Vec3 sum(0.0);
      for (int32_t v : mesh.triangles[f])
        sum += Vec3(mesh.colors[v][0], mesh.colors[v][1], mesh.colors[v][2]);
      colors[f] = sum / (3.0 * 255.0);
      continue;
    }
    const Vec3 element = element_color(ids[f]);
    colors[f] = mode == RenderMode::elements ? element : glm::mix(kNeutral, element, kShadedTint);
  }
  return colors;
}

void bounding_box(const TriMesh& mesh, Vec3* lo, Vec3* hi) {
  *lo = Vec3(std::numeric_limits<double>::infinity());
  *hi = -*lo;
  for (const Tri& t : mesh.triangles) {
    for (int32_t v : t) {
      *lo = glm::min(*lo, mesh.positions[v]);
      *hi = glm::max(*hi, mesh.positions[v]);
    }
  }
}

uint8_t to_byte(double c) { return static_cast<uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

RgbImage render_framed(const TriMesh& mesh, const RenderOptions& options, const OrthographicCamera& camera);

}  // namespace

void validate_render_options(const RenderOptions& options) {
  if (options.width < 1 || options.height < 1 || options.width > kMaxImageSide ||
      options.height > kMaxImageSide)
    throw OptionError("{size} " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                      ": each side must be 1 to " + std::to_string(kMaxImageSide) + " pixels");
  if (options.samples < 1 || options.samples > 4)
    throw InputError("render samples: expected 1 to 4 per side, got " + std::to_string(options.samples),
                     ErrorKind::invalid_option);
  if (options.up < 0 || options.up > 2)
    throw InputError("{up}: expected x, y or z", ErrorKind::invalid_option);
  if (options.close_up && !(options.close_up->radius >= 0.0 && std::isfinite(options.close_up->radius)))
    throw InputError("{radius}: expected a positive distance, got " + std::to_string(options.close_up->radius),
                     ErrorKind::invalid_option);
  if (!(options.margin >= 0.0 && options.margin <= 0.45))
    throw InputError("render margin: expected 0 to 0.45, got " + std::to_string(options.margin),
                     ErrorKind::invalid_option);
}

View parse_view(const std::string& text) {
  if (text == "top") return View::top;
  if (text == "oblique") return View::oblique;
  if (text == "front") return View::front;
  if (text == "side") return View::side;
  throw InputError("{view}: expected top, oblique, front or side, got '" + text + "'",
                   ErrorKind::invalid_option);
}

RenderMode parse_render_mode(const std::string& text) {
  if (text == "shaded") return RenderMode::shaded;
  if (text == "elements") return RenderMode::elements;
  if (text == "colors") return RenderMode::colors;
  throw InputError("{mode}: expected shaded, elements or colors, got '" + text + "'", ErrorKind::invalid_option);
}

int parse_up_axis(const std::string& text) {
  if (text == "x" || text == "y" || text == "z") return text[0] - 'x';
  throw InputError("{up}: expected x, y or z, got '" + text + "'", ErrorKind::invalid_option);
}

RgbImage render_mesh(const TriMesh& mesh, const RenderOptions& options) {
  validate_render_options(options);
  if (mesh.num_faces() == 0) throw InputError("render: the mesh has no faces");
  if (options.up != 2) {
    // A rotation carries the up axis to z (a quarter turn about x for y, a cyclic turn for x): for
    // y up, the model's front (+z) comes to face the front view's camera (-y).
    TriMesh turned = mesh;
    const auto turn = [&](const Vec3& p) { return options.up == 1 ? Vec3(p.x, -p.z, p.y) : Vec3(p.y, p.z, p.x); };
    for (Vec3& p : turned.positions) p = turn(p);
    RenderOptions upright = options;
    upright.up = 2;
    if (upright.close_up) upright.close_up->point = turn(upright.close_up->point);
    return render_mesh(turned, upright);
  }
  if (options.mode == RenderMode::colors && mesh.colors.size() != mesh.positions.size())
    throw InputError("{mode} colors: the mesh has no vertex colours (see meshquilt edit {color_by})",
                     ErrorKind::invalid_option);
  Vec3 lo, hi;
  bounding_box(mesh, &lo, &hi);
  if (options.close_up) {
    const TriMesh near = close_up_elements(mesh, *options.close_up);
    Vec3 near_lo, near_hi;
    bounding_box(near, &near_lo, &near_hi);
    const Vec3 to_centre = 0.5 * (lo + hi) - options.close_up->point;
    RenderOptions framed = options;
    framed.close_up.reset();
    const double length = glm::length(to_centre);
    const Vec3 forward = length > 1e-12 * glm::length(hi - lo) ? to_centre / length : view_direction(options.view);
    return render_framed(near, framed, frame_box_along(near_lo, near_hi, forward, options.width, options.height,
                                                       options.margin));
  }
  return render_framed(mesh, options, frame_box(lo, hi, options.view, options.width, options.height, options.margin));
}

double close_up_radius(const TriMesh& mesh, const CloseUp& close_up) {
  if (close_up.radius > 0.0) return close_up.radius;
  Vec3 lo, hi;
  bounding_box(mesh, &lo, &hi);
  return mesh.triangles.empty() ? 0.0 : 0.1 * glm::length(hi - lo);
}

TriMesh close_up_elements(const TriMesh& mesh, const CloseUp& close_up) {
  const std::vector<int32_t> ids = face_element_ids(mesh);
  std::unordered_set<int32_t> near;
  const double radius = close_up_radius(mesh, close_up);
  const double r2 = radius * radius;
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f]) {
      const Vec3 d = mesh.positions[v] - close_up.point;
      if (glm::dot(d, d) <= r2) near.insert(ids[f]);
    }
  TriMesh result;
  result.positions = mesh.positions;
  if (mesh.colors.size() == mesh.positions.size()) result.colors = mesh.colors;
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    if (near.count(ids[f])) {
      result.triangles.push_back(mesh.triangles[f]);
      result.elements.push_back(ids[f]);
    }
  if (result.triangles.empty())
    throw InputError("render: no element comes within " + std::to_string(radius) + " of the close-up point");
  return result;
}

namespace {

RgbImage render_framed(const TriMesh& mesh, const RenderOptions& options, const OrthographicCamera& camera) {
  const Lights lights = lights_for(camera);
  const std::vector<Vec3> normals = face_normals(mesh);
  const std::vector<Vec3> colors = face_colors(mesh, options.mode, options.plain_element);
  const FaceBvh bvh(mesh);
  const Vec3 background(options.background[0] / 255.0, options.background[1] / 255.0,
                        options.background[2] / 255.0);

  auto shade = [&](double x, double y) {
    const RayHit hit = bvh.ray_cast(camera.ray_origin(x, y), camera.forward);
    if (hit.face < 0) return background;
    Vec3 n = normals[hit.face];
    if (glm::dot(n, lights.head) < 0.0) n = -n;  // two-sided: light the side facing the camera
    const double light =
        kAmbient + kKey * std::max(0.0, glm::dot(n, lights.key)) + kHead * glm::dot(n, lights.head);
    // Capped at 240/255 so a lit face never takes the (lighter) default background's colour.
    return glm::min(colors[hit.face] * light, Vec3(240.0 / 255.0));
  };

  RgbImage image;
  image.width = options.width;
  image.height = options.height;
  image.rgb.resize(static_cast<size_t>(options.width) * options.height * 3);
  const int s = options.samples;
  tbb::parallel_for(0, options.height, [&](int row) {
    for (int column = 0; column < options.width; ++column) {
      Vec3 sum(0.0);
      for (int sy = 0; sy < s; ++sy)
        for (int sx = 0; sx < s; ++sx) sum += shade(column + (sx + 0.5) / s, row + (sy + 0.5) / s);
      const Vec3 c = sum / static_cast<double>(s * s);
      uint8_t* out = &image.rgb[(static_cast<size_t>(row) * options.width + column) * 3];
      out[0] = to_byte(c.r);
      out[1] = to_byte(c.g);
      out[2] = to_byte(c.b);
    }
  });
  return image;
}

}  // namespace

}  // namespace meshquilt
