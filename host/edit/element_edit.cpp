#include "edit/element_edit.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "core/error.h"
#include "render/element_palette.h"

namespace meshquilt {

bool EditRegion::contains(const Vec3& p) const {
  if (kind == Kind::sphere) {
    const Vec3 d = p - centre;
    return d.x * d.x + d.y * d.y + d.z * d.z <= radius * radius;
  }
  return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}

namespace {

void check_request(const ElementView& view, const EditRequest& request) {
  if (!(request.age >= 0.0 && request.age <= 1.0))
    throw InputError("{age}: expected a share in [0, 1], got " + std::to_string(request.age),
                     ErrorKind::invalid_option);
  for (const EditRegion& region : request.remove_inside) {
    if (view.positions.empty())
      throw InputError("a box or sphere needs vertex positions: give {base} to place a texture file",
                       ErrorKind::invalid_option);
    if (region.kind == EditRegion::Kind::box &&
        !(region.lo.x <= region.hi.x && region.lo.y <= region.hi.y && region.lo.z <= region.hi.z))
      throw InputError("{remove_box}: each low corner coordinate must not exceed the high one",
                       ErrorKind::invalid_option);
    if (region.kind == EditRegion::Kind::sphere && !(region.radius >= 0.0))
      throw InputError("{remove_sphere}: the radius must not be negative", ErrorKind::invalid_option);
  }
}

bool listed(const std::vector<int32_t>& list, int32_t id) {
  return std::find(list.begin(), list.end(), id) != list.end();
}

}  // namespace

std::vector<int32_t> elements_to_remove(const ElementView& view, const EditRequest& request,
                                        EditCounts& counts) {
  check_request(view, request);
  // Each element's source (its first face's) and the mean of its vertices.
  std::map<int32_t, int32_t> source;
  std::map<int32_t, std::pair<Vec3, int>> centre;
  for (size_t f = 0; f < view.face_elements.size(); ++f) {
    const int32_t e = view.face_elements[f];
    source.emplace(e, view.face_sources.empty() ? -1 : view.face_sources[f]);
  }
  if (!request.remove_inside.empty()) {
    std::vector<int32_t> vertex_element(view.positions.size(), -1);
    for (size_t f = 0; f < view.triangles.size(); ++f)
      for (int32_t v : view.triangles[f]) vertex_element[v] = view.face_elements[f];
    for (size_t v = 0; v < view.positions.size(); ++v) {
      if (vertex_element[v] < 0) continue;
      auto& [sum, n] = centre[vertex_element[v]];
      sum += view.positions[v];
      ++n;
    }
  }
  counts = {};
  counts.elements = static_cast<int>(source.size());
  std::vector<int32_t> alive;
  std::vector<int32_t> removed;
  for (const auto& [e, s] : source) {
    int* rule = nullptr;
    if (listed(request.remove_elements, e))
      rule = &counts.by_id;
    else if (s >= 0 && listed(request.remove_sources, s))
      rule = &counts.by_source;
    else if (!request.keep_sources.empty() && !listed(request.keep_sources, s))
      rule = &counts.by_keep_source;
    else if (!request.remove_inside.empty()) {
      const auto& [sum, n] = centre[e];
      const Vec3 mean = sum / static_cast<double>(std::max(n, 1));
      for (const EditRegion& region : request.remove_inside)
        if (region.contains(mean)) rule = &counts.inside;
    }
    if (rule) {
      ++*rule;
      removed.push_back(e);
    } else {
      alive.push_back(e);
    }
  }
  // Aging: a share of all the input's elements, drawn from those still alive by a partial
  // Fisher-Yates shuffle on mt19937_64 (its sequence is fixed by the standard).
  const auto wanted = static_cast<size_t>(std::llround(request.age * counts.elements));
  std::mt19937_64 random(request.seed);
  const size_t aged = std::min(wanted, alive.size());
  for (size_t i = 0; i < aged; ++i) {
    const size_t j = i + static_cast<size_t>(random() % (alive.size() - i));
    std::swap(alive[i], alive[j]);
    removed.push_back(alive[i]);
  }
  counts.aged = static_cast<int>(aged);
  counts.kept = counts.elements - static_cast<int>(removed.size());
  std::sort(removed.begin(), removed.end());
  return removed;
}

std::vector<uint8_t> faces_kept(const std::vector<int32_t>& face_elements,
                                const std::vector<int32_t>& removed) {
  std::vector<uint8_t> keep(face_elements.size());
  for (size_t f = 0; f < face_elements.size(); ++f)
    keep[f] = !std::binary_search(removed.begin(), removed.end(), face_elements[f]);
  return keep;
}

TriMesh keep_faces(const TriMesh& mesh, const std::vector<uint8_t>& keep) {
  std::vector<int32_t> index(mesh.positions.size(), -1);
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    if (keep[f])
      for (int32_t v : mesh.triangles[f]) index[v] = 0;
  TriMesh out;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    if (index[v] < 0) continue;
    index[v] = static_cast<int32_t>(out.positions.size());
    out.positions.push_back(mesh.positions[v]);
    if (!mesh.colors.empty()) out.colors.push_back(mesh.colors[v]);
    if (!mesh.origins.empty()) out.origins.push_back(mesh.origins[v]);
  }
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!keep[f]) continue;
    const Tri& t = mesh.triangles[f];
    out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    if (!mesh.elements.empty()) out.elements.push_back(mesh.elements[f]);
    if (!mesh.sources.empty()) out.sources.push_back(mesh.sources[f]);
  }
  return out;
}

std::vector<std::array<uint8_t, 3>> vertex_colors(const TriMesh& mesh, ColorBy by,
                                                  const std::vector<std::array<uint8_t, 3>>& palette) {
  if (by == ColorBy::source && mesh.sources.size() != mesh.triangles.size())
    throw InputError("{color_by} source: the mesh has no per-face source (write it with synth)",
                     ErrorKind::invalid_option);
  const std::vector<int32_t> ids = by == ColorBy::source ? mesh.sources : face_element_ids(mesh);
  const auto color_of = [&](int32_t id) -> std::array<uint8_t, 3> {
    if (!palette.empty()) return palette[static_cast<uint32_t>(id) % palette.size()];
    const Vec3 c = element_color(id);
    const auto byte = [](double x) {
      return static_cast<uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0));
    };
    return {byte(c.x), byte(c.y), byte(c.z)};
  };
  std::vector<std::array<uint8_t, 3>> colors(mesh.positions.size(), {255, 255, 255});
  std::vector<uint8_t> set(mesh.positions.size(), 0);
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int32_t v : mesh.triangles[f])
      if (!set[v]) {
        colors[v] = color_of(ids[f]);
        set[v] = 1;
      }
  return colors;
}

std::vector<std::array<uint8_t, 3>> parse_palette(const std::string& text) {
  std::vector<std::array<uint8_t, 3>> palette;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    std::string entry = text.substr(start, end - start);
    if (!entry.empty() && entry[0] == '#') entry.erase(0, 1);
    const bool hex = entry.size() == 6 && std::all_of(entry.begin(), entry.end(), [](char c) {
                       return std::isxdigit(static_cast<unsigned char>(c));
                     });
    if (!hex)
      throw InputError("{palette}: expected colours as RRGGBB separated by commas, got '" + text + "'",
                       ErrorKind::invalid_option);
    const unsigned long value = std::stoul(entry, nullptr, 16);
    palette.push_back(
        {static_cast<uint8_t>(value >> 16), static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value)});
    start = end + 1;
  }
  return palette;
}

}  // namespace meshquilt
