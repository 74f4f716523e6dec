#include "loom/yarn_profile.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/error.h"

namespace meshquilt {
namespace {

// Fills the entries of `values` (count x width) whose `filled` flag is 0 from the nearest filled
// ones on either side, linearly; `circular` wraps around. false when none is filled.
bool fill_gaps(std::vector<double>& values, std::vector<uint8_t>& filled, size_t count, size_t width, bool circular) {
  std::vector<size_t> known;
  for (size_t i = 0; i < count; ++i)
    if (filled[i]) known.push_back(i);
  if (known.empty()) return false;
  for (size_t i = 0; i < count; ++i) {
    if (filled[i]) continue;
    // The filled neighbours before and after i.
    size_t after = 0;
    while (after < known.size() && known[after] < i) ++after;
    size_t a, b;
    double span, into;
    if (circular) {
      a = known[(after + known.size() - 1) % known.size()];
      b = known[after % known.size()];
      span = static_cast<double>((b + count - a) % count);
      into = static_cast<double>((i + count - a) % count);
    } else {
      a = known[after == 0 ? 0 : after - 1];
      b = known[after == known.size() ? known.size() - 1 : after];
      span = static_cast<double>(b) - static_cast<double>(a);
      into = static_cast<double>(i) - static_cast<double>(a);
    }
    const double w = span > 0.0 ? into / span : 0.0;
    for (size_t k = 0; k < width; ++k) values[i * width + k] = (1.0 - w) * values[a * width + k] + w * values[b * width + k];
  }
  return true;
}

// A yarn's triangles cut by the plane across its run at each station: the section's outline as
// segments in (sideways, up). Its centre is the outline's length-weighted mean; its radius at
// angle a the farthest crossing of the ray from the centre at a with the outline. Exact for any
// tessellation, and measured in the plane the fabric is swept in.
YarnProfile profile_yarn(const std::vector<std::array<Vec3, 3>>& triangles, bool warp, double nominal, double start,
                         double step, size_t stations, int sides, const std::string& what) {
  const auto run_of = [warp](const Vec3& q) { return warp ? q.y : q.x; };
  const auto plan_of = [warp, nominal](const Vec3& q) { return glm::dvec2((warp ? q.x : q.y) - nominal, q.z); };
  std::vector<std::vector<std::array<glm::dvec2, 2>>> outline(stations);
  for (const std::array<Vec3, 3>& t : triangles) {
    double lo = run_of(t[0]), hi = lo;
    for (const Vec3& q : t) {
      lo = std::min(lo, run_of(q));
      hi = std::max(hi, run_of(q));
    }
    const long first = std::max(0L, static_cast<long>(std::ceil((lo - start) / step)));
    const long last = std::min(static_cast<long>(stations) - 1, static_cast<long>(std::floor((hi - start) / step)));
    for (long s = first; s <= last; ++s) {
      const double cut = start + step * static_cast<double>(s);
      std::array<glm::dvec2, 2> ends;
      int found = 0;
      for (int e = 0; e < 3 && found < 2; ++e) {
        const Vec3 &p = t[e], &q = t[(e + 1) % 3];
        const double a = run_of(p) - cut, b = run_of(q) - cut;
        if ((a < 0.0) == (b < 0.0) || a == b) continue;
        const double w = a / (a - b);
        ends[found++] = (1.0 - w) * plan_of(p) + w * plan_of(q);
      }
      if (found == 2) outline[s].push_back(ends);
    }
  }
  std::vector<double> centre(2 * stations, 0.0);
  std::vector<uint8_t> filled(stations, 0);
  for (size_t s = 0; s < stations; ++s) {
    glm::dvec2 sum(0.0);
    double length = 0.0;
    for (const auto& seg : outline[s]) {
      const double l = glm::length(seg[1] - seg[0]);
      sum += l * 0.5 * (seg[0] + seg[1]);
      length += l;
    }
    if (length > 0.0) {
      centre[2 * s] = sum.x / length;
      centre[2 * s + 1] = sum.y / length;
      filled[s] = 1;
    }
  }
  if (!fill_gaps(centre, filled, stations, 2, false))
    throw InputError(what + " has no vertex along its run", ErrorKind::invalid_mesh);
  const size_t k_count = static_cast<size_t>(sides);
  std::vector<double> radius(stations * k_count, 0.0);
  std::vector<uint8_t> station_filled(stations, 0);
  for (size_t s = 0; s < stations; ++s) {
    if (!filled[s]) continue;
    const glm::dvec2 c(centre[2 * s], centre[2 * s + 1]);
    bool all = true;
    for (size_t k = 0; k < k_count; ++k) {
      const double a = 2.0 * kPi * static_cast<double>(k) / sides;
      const glm::dvec2 d(std::cos(a), std::sin(a));
      double far = -1.0;
      for (const auto& seg : outline[s]) {
        // c + t d = seg[0] + u (seg[1] - seg[0]), t >= 0, 0 <= u <= 1.
        const glm::dvec2 e = seg[1] - seg[0], f = seg[0] - c;
        const double den = d.x * e.y - d.y * e.x;
        if (std::abs(den) < 1e-300) continue;
        const double t = (f.x * e.y - f.y * e.x) / den, u = (f.x * d.y - f.y * d.x) / den;
        if (t >= 0.0 && u >= 0.0 && u <= 1.0) far = std::max(far, t);
      }
      if (far < 0.0) all = false;
      radius[s * k_count + k] = far;
    }
    station_filled[s] = all ? 1 : 0;
  }
  fill_gaps(radius, station_filled, stations, k_count, false);
  YarnProfile profile;
  for (size_t s = 0; s < stations; ++s) profile.centre.emplace_back(centre[2 * s], centre[2 * s + 1]);
  profile.radius = std::move(radius);
  return profile;
}

}  // namespace

ExemplarProfiles profile_exemplar(const TriMesh& mesh, const ExemplarWeave& weave, int per_pitch, int sides,
                                  const std::string& name) {
  ExemplarProfiles out;
  out.weave = weave;
  out.per_pitch = per_pitch;
  out.sides = sides;
  const std::vector<int32_t> face_elements = yarn_face_elements(mesh);
  int32_t count = 0;
  for (int32_t e : face_elements) count = std::max(count, e + 1);
  std::vector<std::vector<std::array<Vec3, 3>>> points(static_cast<size_t>(count));
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    points[face_elements[f]].push_back({registered_point(weave, mesh.positions[t[0]]),
                                        registered_point(weave, mesh.positions[t[1]]),
                                        registered_point(weave, mesh.positions[t[2]])});
  }
  const int nw = weave.pattern.warps, nf = weave.pattern.wefts;
  for (int i = 0; i < nw; ++i)
    out.warps.push_back(profile_yarn(points[weave.warp_elements[i]], true, weave.origin.x + i * weave.pitch.x,
                                     weave.origin.y - 0.5 * weave.pitch.y, weave.pitch.y / per_pitch,
                                     static_cast<size_t>(nf * per_pitch + 1), sides,
                                     name + ": warp " + std::to_string(i)));
  for (int j = 0; j < nf; ++j)
    out.wefts.push_back(profile_yarn(points[weave.weft_elements[j]], false, weave.origin.y + j * weave.pitch.y,
                                     weave.origin.x - 0.5 * weave.pitch.x, weave.pitch.x / per_pitch,
                                     static_cast<size_t>(nw * per_pitch + 1), sides,
                                     name + ": weft " + std::to_string(j)));
  return out;
}

}  // namespace meshquilt
