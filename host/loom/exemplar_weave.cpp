#include "loom/exemplar_weave.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "mesh/topology.h"

namespace meshquilt {
namespace {

struct Span {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return lo > hi; }
  double mid() const { return 0.5 * (lo + hi); }
};

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The weave's axis modulo a quarter turn: the circular mean of four times each element's main
// direction in x-y, weighted by how elongated the element is.
double weave_tilt(const TriMesh& mesh, const std::vector<std::vector<int32_t>>& vertices_of) {
  double s = 0.0, c = 0.0;
  for (const std::vector<int32_t>& vertices : vertices_of) {
    glm::dvec2 mean(0.0);
    for (int32_t v : vertices) mean += glm::dvec2(mesh.positions[v]);
    mean /= static_cast<double>(vertices.size());
    double xx = 0.0, yy = 0.0, xy = 0.0;
    for (int32_t v : vertices) {
      const glm::dvec2 d = glm::dvec2(mesh.positions[v]) - mean;
      xx += d.x * d.x;
      yy += d.y * d.y;
      xy += d.x * d.y;
    }
    const double theta = 0.5 * std::atan2(2.0 * xy, xx - yy);
    const double spread = std::sqrt((xx - yy) * (xx - yy) + 4.0 * xy * xy);  // lambda1 - lambda2
    s += spread * std::sin(4.0 * theta);
    c += spread * std::cos(4.0 * theta);
  }
  return 0.25 * std::atan2(s, c);
}

// Evenly spaced centres: the median step, refusing spacings off it by more than a fifth.
double regular_pitch(const std::vector<double>& centres, const std::string& name, const char* what) {
  std::vector<double> steps;
  for (size_t k = 1; k < centres.size(); ++k) steps.push_back(centres[k] - centres[k - 1]);
  const double pitch = median(steps);
  for (size_t k = 0; k < steps.size(); ++k)
    if (!(std::abs(steps[k] - pitch) <= 0.2 * pitch))
      throw InputError(name + ": the " + what + " are not evenly spaced (" + std::to_string(steps[k]) +
                           " between two, pitch " + std::to_string(pitch) + "); crossings cannot be registered",
                       ErrorKind::invalid_mesh);
  return pitch;
}

}  // namespace

Vec3 registered_point(const ExemplarWeave& weave, const Vec3& q) {
  const double cs = std::cos(weave.tilt), sn = std::sin(weave.tilt);
  return Vec3(cs * q.x + sn * q.y, -sn * q.x + cs * q.y, q.z);
}

std::vector<int32_t> yarn_face_elements(const TriMesh& mesh) {
  return mesh.elements.size() == mesh.num_faces() ? mesh.elements : face_components(mesh);
}

ExemplarWeave register_exemplar(const TriMesh& mesh, const std::string& name) {
  const std::vector<int32_t> face_elements = yarn_face_elements(mesh);
  int32_t count = 0;
  for (int32_t e : face_elements) count = std::max(count, e + 1);
  std::vector<std::vector<int32_t>> vertices_of(static_cast<size_t>(count));
  {
    std::vector<int32_t> seen(mesh.num_vertices(), -1);
    for (size_t f = 0; f < mesh.num_faces(); ++f)
      for (int32_t v : mesh.triangles[f])
        if (seen[v] != face_elements[f]) {
          seen[v] = face_elements[f];
          vertices_of[face_elements[f]].push_back(v);
        }
  }
  std::vector<int32_t> element_of_slot;  // vertices_of compacted: slot -> element id
  for (int32_t e = 0; e < count; ++e)
    if (!vertices_of[e].empty()) element_of_slot.push_back(e);
  std::erase_if(vertices_of, [](const std::vector<int32_t>& v) { return v.empty(); });
  if (vertices_of.empty()) throw InputError(name + ": no yarns (the mesh has no faces)", ErrorKind::invalid_mesh);

  ExemplarWeave weave;
  weave.tilt = weave_tilt(mesh, vertices_of);
  std::vector<Vec3> p(mesh.num_vertices());
  for (size_t v = 0; v < p.size(); ++v) p[v] = registered_point(weave, mesh.positions[v]);

  // Yarns by their run: warps along y, wefts along x.
  struct Yarn {
    int32_t element;
    double centre;  // x of a warp, y of a weft
    double half_thickness;
  };
  std::vector<Yarn> warps, wefts;
  size_t element_index = 0;
  for (const std::vector<int32_t>& vertices : vertices_of) {
    Span x, y;
    for (int32_t v : vertices) {
      x.add(p[v].x);
      y.add(p[v].y);
    }
    const double dx = x.hi - x.lo, dy = y.hi - y.lo;
    const int32_t element = element_of_slot[element_index++];
    if (dy >= 2.0 * dx)
      warps.push_back({element, x.mid(), 0.5 * dx});
    else if (dx >= 2.0 * dy)
      wefts.push_back({element, y.mid(), 0.5 * dy});
    else
      throw InputError(name + ": element " + std::to_string(element) +
                           " is not a yarn (not twice as long along the weave as across it)",
                       ErrorKind::invalid_mesh);
  }
  if (warps.size() < 3 || wefts.size() < 3)
    throw InputError(name + ": " + std::to_string(warps.size()) + " warps and " + std::to_string(wefts.size()) +
                         " wefts; an exemplar needs at least three of each",
                     ErrorKind::invalid_mesh);
  const auto by_centre = [](const Yarn& a, const Yarn& b) { return a.centre < b.centre; };
  std::sort(warps.begin(), warps.end(), by_centre);
  std::sort(wefts.begin(), wefts.end(), by_centre);
  std::vector<double> xs, ys, thickness;
  for (const Yarn& w : warps) {
    xs.push_back(w.centre);
    weave.warp_elements.push_back(w.element);
    thickness.push_back(w.half_thickness);
  }
  for (const Yarn& w : wefts) {
    ys.push_back(w.centre);
    weave.weft_elements.push_back(w.element);
    thickness.push_back(w.half_thickness);
  }
  weave.pitch = glm::dvec2(regular_pitch(xs, name, "warps"), regular_pitch(ys, name, "wefts"));
  weave.origin = glm::dvec2(xs[0], ys[0]);
  weave.yarn_radius = median(thickness);

  // Each yarn's height where it crosses each yarn of the other direction: the middle of its
  // vertices' heights within a quarter pitch of the crossing.
  const int nw = static_cast<int>(warps.size()), nf = static_cast<int>(wefts.size());
  std::vector<int32_t> warp_slot(static_cast<size_t>(count), -1), weft_slot(static_cast<size_t>(count), -1);
  for (int i = 0; i < nw; ++i) warp_slot[warps[i].element] = i;
  for (int j = 0; j < nf; ++j) weft_slot[wefts[j].element] = j;
  std::vector<Span> warp_z(static_cast<size_t>(nw) * nf), weft_z(static_cast<size_t>(nw) * nf);
  std::vector<uint8_t> visited(mesh.num_vertices(), 0);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f]) {
      if (visited[v]) continue;
      visited[v] = 1;
      const int32_t e = face_elements[f];
      if (warp_slot[e] >= 0) {
        const double t = (p[v].y - weave.origin.y) / weave.pitch.y;
        const long j = std::lround(t);
        if (j >= 0 && j < nf && std::abs(t - static_cast<double>(j)) < 0.25)
          warp_z[static_cast<size_t>(j) * nw + warp_slot[e]].add(p[v].z);
      } else if (weft_slot[e] >= 0) {
        const double t = (p[v].x - weave.origin.x) / weave.pitch.x;
        const long i = std::lround(t);
        if (i >= 0 && i < nw && std::abs(t - static_cast<double>(i)) < 0.25)
          weft_z[static_cast<size_t>(weft_slot[e]) * nw + i].add(p[v].z);
      }
    }
  weave.pattern.warps = nw;
  weave.pattern.wefts = nf;
  weave.pattern.warp_over.assign(static_cast<size_t>(nw) * nf, 0);
  for (int j = 0; j < nf; ++j)
    for (int i = 0; i < nw; ++i) {
      const Span& a = warp_z[static_cast<size_t>(j) * nw + i];
      const Span& b = weft_z[static_cast<size_t>(j) * nw + i];
      if (a.empty() || b.empty() || !(std::abs(a.mid() - b.mid()) > 1e-3 * std::min(weave.pitch.x, weave.pitch.y)))
        throw InputError(name + ": warp " + std::to_string(i) + " and weft " + std::to_string(j) +
                             " do not cross one above the other where the grid says; crossings cannot be registered",
                         ErrorKind::invalid_mesh);
      weave.pattern.warp_over[static_cast<size_t>(j) * nw + i] = a.mid() > b.mid() ? 1 : 0;
    }
  return weave;
}

}  // namespace meshquilt
