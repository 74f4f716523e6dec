#include "swatch/weave.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "core/constants.h"
#include "core/error.h"
#include "swatch/tube_mesh.h"

namespace meshquilt {
namespace {


// Messages name the parameters at fault as {name} (OptionError).
[[noreturn]] void invalid(const std::string& message) { throw OptionError("weave: " + message); }
[[noreturn]] void invalid(const std::string& parameter, const std::string& problem) {
  invalid("{" + parameter + "} " + problem);
}

// Height of a yarn centreline at parameter u (in pitches, crossing k centred at u = k + 1/2),
// given the sign of the yarn at each crossing: half cosine waves between crossings.
template <class Sign>
double centreline_height(double u, double amplitude, const Sign& sign) {
  const double v = u - 0.5;
  const int k = static_cast<int>(std::floor(v));
  const double f = v - k;
  const double a = sign(k), b = sign(k + 1);
  return amplitude * (0.5 * (a + b) + 0.5 * (a - b) * std::cos(kPi * f));
}

// d(height)/du of centreline_height.
template <class Sign>
double centreline_slope(double u, double amplitude, const Sign& sign) {
  const double v = u - 0.5;
  const int k = static_cast<int>(std::floor(v));
  const double f = v - k;
  return -amplitude * 0.5 * (sign(k) - sign(k + 1)) * kPi * std::sin(kPi * f);
}

int resolve_count(int given, int repeat, int hint) {
  if (given != 0) return given;
  return std::max(1, static_cast<int>(std::lround(static_cast<double>(hint) / repeat))) * repeat;
}

// Smallest distance between the centrelines of a warp and a weft near their crossing. It depends
// only on the signs of the two yarns at the crossings within one pitch, so each local
// configuration is measured once: a grid over the window where both offsets are below `needed`
// (outside it the offsets alone keep the yarns apart), less the grid's Lipschitz error.
double crossing_clearance(int warp_signs, int weft_signs, const WeaveOptions& o, double needed) {
  auto bit_sign = [](int bits, int k) { return ((bits >> (k + 2)) & 1) ? 1.0 : -1.0; };
  auto warp_sign = [&](int k) { return bit_sign(warp_signs, k); };
  auto weft_sign = [&](int k) { return bit_sign(weft_signs, k); };
  const double window = needed;  // below one pitch, so crossings k-2..k+2 decide the heights
  constexpr int kSteps = 200;
  const double h = 2.0 * window / kSteps;
  double best = INFINITY;
  for (int a = 0; a <= kSteps; ++a) {
    const double dy = -window + a * h;  // along the warp
    const double zw = centreline_height(0.5 + dy / o.pitch, o.amplitude, warp_sign);
    for (int b = 0; b <= kSteps; ++b) {
      const double dx = -window + b * h;  // along the weft
      const double zf = centreline_height(0.5 + dx / o.pitch, o.amplitude, weft_sign);
      best = std::min(best, std::sqrt(dx * dx + dy * dy + (zw - zf) * (zw - zf)));
    }
  }
  const double max_slope = o.amplitude * kPi / o.pitch;
  return best - std::sqrt(1.0 + max_slope * max_slope) * h;
}

void validate(const WeaveOptions& o, int warps, int wefts) {
  const WeavePattern& p = o.pattern;
  if (p.warps < 1 || p.wefts < 1 || p.warp_over.size() != static_cast<size_t>(p.warps) * p.wefts) {
    invalid("empty or malformed pattern");
  }
  if (warps < 1 || (o.whole_repeats && warps % p.warps != 0)) {
    invalid("warps", std::to_string(warps) + " is not a positive multiple of the pattern's " + std::to_string(p.warps) + " ends");
  }
  if (wefts < 1 || (o.whole_repeats && wefts % p.wefts != 0)) {
    invalid("wefts", std::to_string(wefts) + " is not a positive multiple of the pattern's " + std::to_string(p.wefts) + " picks");
  }
  if (warps > 4096 || wefts > 4096) invalid("more than 4096 yarns in a direction");
  if (o.segments_per_pitch < 2) invalid("segments", "must be >= 2");
  if (o.sides < 3) invalid("sides", "must be >= 3");
  if (!(o.pitch > 0.0) || !std::isfinite(o.pitch)) invalid("pitch", "must be positive");
  if (!(o.yarn_radius > 0.0) || !std::isfinite(o.yarn_radius)) invalid("yarn_radius", "must be positive");
  if (!(o.amplitude > 0.0) || !std::isfinite(o.amplitude)) invalid("amplitude", "must be positive");

  const double curvature = o.amplitude * kPi * kPi / (o.pitch * o.pitch);  // at a crossing, the largest
  if (o.yarn_radius * curvature >= 0.9) {
    std::ostringstream m;
    m << "{yarn_radius} " << o.yarn_radius << " exceeds 0.9x the centreline's radius of curvature "
      << 1.0 / curvature << ": the yarn would fold; lower {amplitude} or {yarn_radius}";
    invalid(m.str());
  }
  // On the inside of a bend the tube's surface is concave along the yarn, so the facets there
  // stand out of the round tube: by the sagitta of a chord of the inner arc, whose radius is
  // 1/curvature - radius and whose chords are (1 - radius curvature) times the centreline's.
  const double max_slope = o.amplitude * kPi / o.pitch;
  const double chord = o.pitch / o.segments_per_pitch * std::sqrt(1.0 + max_slope * max_slope);
  const double bulge = chord * chord * curvature * (1.0 - o.yarn_radius * curvature) / 8.0;
  const double needed = 2.0 * (o.yarn_radius + bulge);
  if (o.pitch <= needed) {
    std::ostringstream m;
    m << "{pitch} " << o.pitch << " must exceed the yarn diameter " << needed << " so that parallel yarns do not touch";
    invalid(m.str());
  }
  // A single direction has no crossings; its crimp is only a shape.
  if (o.yarns != WeaveYarns::both) return;
  // Signs at crossings k-2..k+2 (bit k+2 set: on top) of the warp and of the weft. The pattern
  // wraps, so a count that is not a whole repeat meets no configuration missing here.
  std::map<std::pair<int, int>, double> measured;
  for (int j = 0; j < p.wefts; ++j) {
    for (int i = 0; i < p.warps; ++i) {
      int warp_bits = 0, weft_bits = 0;
      for (int k = -2; k <= 2; ++k) {
        warp_bits |= (p.over(i, j + k) ? 1 : 0) << (k + 2);
        weft_bits |= (p.over(i + k, j) ? 0 : 1) << (k + 2);
      }
      const auto key = std::make_pair(warp_bits, weft_bits);
      if (measured.count(key) != 0) continue;
      const double clearance = crossing_clearance(warp_bits, weft_bits, o, needed);
      measured[key] = clearance;
      if (clearance <= needed) {
        std::ostringstream m;
        m << "yarns would touch at crossing (warp " << i << ", weft " << j << "): centrelines come within " << clearance
          << ", which needs to exceed " << needed << "; raise {amplitude} or lower {yarn_radius}";
        invalid(m.str());
      }
    }
  }
}

}  // namespace

WeaveOptions WeaveOptions::small() {
  WeaveOptions o;
  o.yarns_hint = 4;
  o.segments_per_pitch = 4;
  o.sides = 6;
  return o;
}

WeaveOptions WeaveOptions::wire() {
  WeaveOptions o;
  o.warps = o.wefts = 9;
  o.pitch = 1.0;
  o.yarn_radius = 0.08;
  o.amplitude = 0.12;
  o.segments_per_pitch = 8;
  o.sides = 8;
  o.whole_repeats = false;  // nine is odd; the plain repeat is two
  return o;
}

WeaveOptions WeaveOptions::small_wire() {
  WeaveOptions o = wire();
  o.warps = o.wefts = 5;
  o.segments_per_pitch = 4;
  o.sides = 5;
  return o;
}

glm::ivec2 weave_yarn_counts(const WeaveOptions& o) {
  return {resolve_count(o.warps, std::max(o.pattern.warps, 1), o.yarns_hint),
          resolve_count(o.wefts, std::max(o.pattern.wefts, 1), o.yarns_hint)};
}

glm::dvec2 weave_period(const WeaveOptions& o) {
  const glm::ivec2 counts = weave_yarn_counts(o);
  return {counts.x * o.pitch, counts.y * o.pitch};
}

TriMesh make_weave(const WeaveOptions& o) {
  const glm::ivec2 counts = weave_yarn_counts(o);
  const int warps = counts.x, wefts = counts.y;
  validate(o, warps, wefts);
  TriMesh mesh;
  std::vector<Vec3> centre, normal, tangent;
  auto sweep = [&](int yarns, int length, bool warp) {
    const int points = length * o.segments_per_pitch + 1;
    centre.resize(points);
    tangent.resize(points);
    normal.assign(points, warp ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    for (int n = 0; n < yarns; ++n) {
      // A warp is on top where the pattern says so; a weft where it does not.
      auto sign = [&](int k) { return (warp ? o.pattern.over(n, k) : !o.pattern.over(k, n)) ? 1.0 : -1.0; };
      const double across = (n + 0.5) * o.pitch;
      for (int k = 0; k < points; ++k) {
        const double u = static_cast<double>(k) / o.segments_per_pitch;
        const double along = u * o.pitch;
        const double z = centreline_height(u, o.amplitude, sign);
        const double dz = centreline_slope(u, o.amplitude, sign) / o.pitch;
        centre[k] = warp ? Vec3(across, along, z) : Vec3(along, across, z);
        tangent[k] = warp ? Vec3(0.0, 1.0, dz) : Vec3(1.0, 0.0, dz);
      }
      // Exact tangents make the end sections periodic: the cap at one border is the cap at the
      // other shifted by the period, so tiled copies continue each yarn without a kink.
      const int32_t element = warp || o.yarns == WeaveYarns::wefts ? n : warps + n;
      append_tube(mesh, centre, normal, o.yarn_radius, o.sides, TubeEnds::capped, element, tangent);
    }
  };
  if (o.yarns != WeaveYarns::wefts) sweep(warps, wefts, true);
  if (o.yarns != WeaveYarns::warps) sweep(wefts, warps, false);
  return mesh;
}

}  // namespace meshquilt
