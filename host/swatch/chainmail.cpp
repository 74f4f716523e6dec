#include "swatch/chainmail.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "swatch/tube_mesh.h"

namespace meshquilt {
namespace {


struct Ring {
  Vec3 centre;
  Vec3 normal;  // of the ring's plane
  Vec3 e1, e2;  // orthonormal axes in the ring's plane
};

// Rings of even rows lean one way and rings of odd rows the other; odd rows sit half a pitch
// over in x so that every ring lies between two rings of each adjacent row.
Ring lattice_ring(const ChainmailOptions& o, int column, int row) {
  const double t = o.tilt_degrees * kPi / 180.0;
  const int parity = ((row % 2) + 2) % 2;
  const double s = parity == 0 ? 1.0 : -1.0;
  Ring ring;
  ring.centre = Vec3((column + 0.5 * parity) * o.pitch_x, row * o.pitch_y, 0.0);
  ring.normal = Vec3(s * std::sin(t), 0.0, std::cos(t));
  ring.e1 = Vec3(std::cos(t), 0.0, -s * std::sin(t));
  ring.e2 = Vec3(0.0, 1.0, 0.0);
  return ring;
}

Vec3 ring_point(const Ring& ring, double radius, double angle) {
  return ring.centre + radius * (std::cos(angle) * ring.e1 + std::sin(angle) * ring.e2);
}

// Distance from a point to a circle, in closed form.
double point_circle_distance(const Vec3& p, const Ring& ring, double radius) {
  const Vec3 q = p - ring.centre;
  const double h = glm::dot(q, ring.normal);
  const double rho = glm::length(q - h * ring.normal);
  return std::sqrt(h * h + (rho - radius) * (rho - radius));
}

constexpr int kProbeSamples = 4096;

// Lower bound on the distance between two circles of equal radius: the closed-form distance from
// samples of one to the other, less the largest distance of any point of the circle to its nearest
// sample (an arc of pi R / K), so the bound holds whatever the sampling misses.
double circle_clearance(const Ring& a, const Ring& b, double radius) {
  double best = INFINITY;
  for (int k = 0; k < kProbeSamples; ++k) {
    best = std::min(best, point_circle_distance(ring_point(b, radius, 2.0 * kPi * k / kProbeSamples), a, radius));
  }
  return best - kPi * radius / kProbeSamples;
}

// Linking of two circles: does b pierce a's disk an odd number of times?
bool circles_linked(const Ring& a, const Ring& b, double radius) {
  int piercings = 0;
  Vec3 p = ring_point(b, radius, 0.0);
  double dp = glm::dot(p - a.centre, a.normal);
  for (int k = 1; k <= kProbeSamples; ++k) {
    const Vec3 q = ring_point(b, radius, 2.0 * kPi * k / kProbeSamples);
    const double dq = glm::dot(q - a.centre, a.normal);
    if ((dp < 0.0) != (dq < 0.0)) {
      const Vec3 x = p + (dp / (dp - dq)) * (q - p);
      if (glm::length(x - a.centre) < radius) ++piercings;
    }
    p = q;
    dp = dq;
  }
  return piercings % 2 == 1;
}

// Messages name the parameters at fault as {name} (OptionError).
[[noreturn]] void invalid(const std::string& message) { throw OptionError("chainmail: " + message); }
[[noreturn]] void invalid(const std::string& parameter, const std::string& problem) {
  invalid("{" + parameter + "} " + problem);
}

void validate(const ChainmailOptions& o) {
  if (o.rows < 2 || o.rows % 2 != 0) invalid("rows", "must be an even number >= 2 (got " + std::to_string(o.rows) + ")");
  if (o.columns < 1) invalid("columns", "must be >= 1 (got " + std::to_string(o.columns) + ")");
  if (o.ring_segments < 8) invalid("ring_segments", "must be >= 8");
  if (o.wire_segments < 3) invalid("wire_segments", "must be >= 3");
  if (!(o.ring_radius > 0.0) || !std::isfinite(o.ring_radius)) invalid("ring_radius", "must be positive");
  if (!(o.wire_radius > 0.0) || !(o.wire_radius < 0.5 * o.ring_radius))
    invalid("wire_radius", "must be positive and below half the ring radius");
  if (!(o.pitch_x > 0.0) || !(o.pitch_y > 0.0) || !std::isfinite(o.pitch_x) || !std::isfinite(o.pitch_y))
    invalid("pitch_x", "and {pitch_y} must be positive");
  if (!(o.tilt_degrees > 0.0 && o.tilt_degrees < 90.0)) invalid("tilt", "must lie in (0, 90) degrees");

  // Every pair of lattice rings near enough to touch or link, from a ring of each row parity:
  // the diagonal neighbours (one row over, half a pitch aside) must link, no other pair may, and
  // no two wires may come closer than their diameters plus what the facets bulge out.
  const double R = o.ring_radius;
  const double facet_bulge = (R + o.wire_radius) * (1.0 - std::cos(kPi / o.ring_segments));
  const double needed = 2.0 * (o.wire_radius + facet_bulge);
  for (int parity = 0; parity < 2; ++parity) {
    const Ring a = lattice_ring(o, 0, parity);
    const int reach_x = static_cast<int>(std::ceil(2.0 * (R + o.wire_radius) / o.pitch_x)) + 1;
    const int reach_y = static_cast<int>(std::ceil(2.0 * (R + o.wire_radius) / o.pitch_y)) + 1;
    for (int dr = -reach_y; dr <= reach_y; ++dr) {
      for (int dc = -reach_x; dc <= reach_x; ++dc) {
        if (dr == 0 && dc == 0) continue;
        const Ring b = lattice_ring(o, dc, parity + dr);
        const Vec3 offset = b.centre - a.centre;
        if (glm::length(offset) > 2.0 * (R + o.wire_radius) + needed) continue;
        const bool diagonal = std::abs(dr) == 1 && std::abs(std::abs(offset.x) - 0.5 * o.pitch_x) < 1e-9 * o.pitch_x;
        if (circles_linked(a, b, R) != diagonal) {
          std::ostringstream m;
          m << "rings offset by (" << offset.x << ", " << offset.y << ") " << (diagonal ? "do not link" : "link")
            << ": {pitch_x}/{pitch_y}/{tilt}/{ring_radius} do not give a 4-in-1 weave";
          invalid(m.str());
        }
        const double clearance = circle_clearance(a, b, R);
        if (clearance <= needed) {
          std::ostringstream m;
          m << "neighbouring rings would touch: their wire centrelines come within " << clearance
            << ", which needs to exceed " << needed << " ({wire_radius} " << o.wire_radius
            << " with the facets); use a thinner wire or wider pitches";
          invalid(m.str());
        }
      }
    }
  }
}

}  // namespace

ChainmailOptions ChainmailOptions::small() {
  ChainmailOptions o;
  // Four rows: a swatch must hold one period of the pattern (two rows, leaning either way) plus
  // the overlap a patch matches on; with two rows a patch can only add a row of the wrong lean,
  // and the output falls apart into strips.
  o.rows = 4;
  o.columns = 2;
  o.ring_segments = 16;
  o.wire_segments = 6;
  return o;
}

glm::dvec2 chainmail_period(const ChainmailOptions& options) {
  return {options.columns * options.pitch_x, options.rows * options.pitch_y};
}

TriMesh make_chainmail(const ChainmailOptions& options) {
  validate(options);
  TriMesh mesh;
  std::vector<Vec3> centre(options.ring_segments), normal(options.ring_segments);
  for (int row = 0; row < options.rows; ++row) {
    for (int column = 0; column < options.columns; ++column) {
      const Ring ring = lattice_ring(options, column, row);
      for (int k = 0; k < options.ring_segments; ++k) {
        const double angle = 2.0 * kPi * k / options.ring_segments;
        centre[k] = ring_point(ring, options.ring_radius, angle);
        normal[k] = std::cos(angle) * ring.e1 + std::sin(angle) * ring.e2;
      }
      append_tube(mesh, centre, normal, options.wire_radius, options.wire_segments, TubeEnds::loop,
                  row * options.columns + column);
    }
  }
  return mesh;
}

}  // namespace meshquilt
