#include "loom/yarn_profile.h"

#include <cmath>

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

YarnProfile profile_yarn(const std::vector<Vec3>& points, bool warp, double nominal, double start, double step,
                         size_t stations, int sides, const std::string& what) {
  // Run, sideways and up of a point in the yarn's own terms.
  const auto run_of = [warp](const Vec3& q) { return warp ? q.y : q.x; };
  const auto side_of = [warp, nominal](const Vec3& q) { return (warp ? q.x : q.y) - nominal; };
  std::vector<double> centre(2 * stations, 0.0), count(stations, 0.0);
  const auto station_of = [&](const Vec3& q) {
    const long s = std::lround((run_of(q) - start) / step);
    return s >= 0 && s < static_cast<long>(stations) ? s : -1L;
  };
  for (const Vec3& q : points)
    if (const long s = station_of(q); s >= 0) {
      centre[2 * s] += side_of(q);
      centre[2 * s + 1] += q.z;
      count[s] += 1.0;
    }
  std::vector<uint8_t> filled(stations, 0);
  for (size_t s = 0; s < stations; ++s)
    if (count[s] > 0.0) {
      centre[2 * s] /= count[s];
      centre[2 * s + 1] /= count[s];
      filled[s] = 1;
    }
  if (!fill_gaps(centre, filled, stations, 2, false))
    throw InputError(what + " has no vertex along its run", ErrorKind::invalid_mesh);

  const size_t k_count = static_cast<size_t>(sides);
  std::vector<double> radius(stations * k_count, 0.0), hits(stations * k_count, 0.0);
  const double sector = 2.0 * kPi / sides;
  for (const Vec3& q : points)
    if (const long s = station_of(q); s >= 0) {
      const double dx = side_of(q) - centre[2 * s], dz = q.z - centre[2 * s + 1];
      const long k = ((std::lround(std::atan2(dz, dx) / sector) % sides) + sides) % sides;
      radius[s * k_count + k] += std::hypot(dx, dz);
      hits[s * k_count + k] += 1.0;
    }
  std::vector<uint8_t> station_filled(stations, 0);
  for (size_t s = 0; s < stations; ++s) {
    std::vector<double> ring(k_count);
    std::vector<uint8_t> seen(k_count, 0);
    for (size_t k = 0; k < k_count; ++k)
      if (hits[s * k_count + k] > 0.0) {
        ring[k] = radius[s * k_count + k] / hits[s * k_count + k];
        seen[k] = 1;
      }
    station_filled[s] = fill_gaps(ring, seen, k_count, 1, true) ? 1 : 0;
    for (size_t k = 0; k < k_count; ++k) radius[s * k_count + k] = ring[k];
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
  std::vector<std::vector<Vec3>> points(static_cast<size_t>(count));
  std::vector<int32_t> seen(mesh.num_vertices(), -1);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f])
      if (seen[v] != face_elements[f]) {
        seen[v] = face_elements[f];
        points[face_elements[f]].push_back(registered_point(weave, mesh.positions[v]));
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
