#include "spatial/exact_predicates.h"

#include <cmath>
#include <limits>
#include <vector>

namespace meshquilt {
namespace {

// Expansions (Shewchuk 1997): sums of non-overlapping doubles in increasing magnitude, so that
// the sign of the sum is the sign of the last non-zero component. Only the rare near-degenerate
// cases reach this code, so clarity wins over speed here.
using Expansion = std::vector<double>;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon() / 2.0;  // 2^-53
constexpr double kO3dErrBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
constexpr double kO2dErrBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;

void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

Expansion difference(double a, double b) {
  double x, y;
  two_sum(a, -b, x, y);
  return {y, x};
}

// Grow-Expansion with zero elimination.
Expansion grow(const Expansion& e, double b) {
  Expansion h;
  h.reserve(e.size() + 1);
  double q = b;
  for (double ei : e) {
    double sum, err;
    two_sum(q, ei, sum, err);
    if (err != 0.0) h.push_back(err);
    q = sum;
  }
  if (q != 0.0 || h.empty()) h.push_back(q);
  return h;
}

Expansion sum(const Expansion& e, const Expansion& f) {
  Expansion h = e;
  for (double fi : f) h = grow(h, fi);
  return h;
}

// Scale-Expansion with zero elimination.
Expansion scale(const Expansion& e, double b) {
  Expansion h;
  if (e.empty()) return h;
  double q, hh;
  two_product(e[0], b, q, hh);
  if (hh != 0.0) h.push_back(hh);
  for (size_t i = 1; i < e.size(); ++i) {
    double t1, t0;
    two_product(e[i], b, t1, t0);
    double s, err;
    two_sum(q, t0, s, err);
    if (err != 0.0) h.push_back(err);
    two_sum(t1, s, q, err);
    if (err != 0.0) h.push_back(err);
  }
  if (q != 0.0 || h.empty()) h.push_back(q);
  return h;
}

Expansion product(const Expansion& e, const Expansion& f) {
  Expansion h{0.0};
  for (double fi : f) h = sum(h, scale(e, fi));
  return h;
}

Expansion negate(Expansion e) {
  for (double& x : e) x = -x;
  return e;
}

int sign_of(const Expansion& e) {
  for (auto it = e.rbegin(); it != e.rend(); ++it) {
    if (*it > 0.0) return 1;
    if (*it < 0.0) return -1;
  }
  return 0;
}

int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

// det[b - a, c - a] with exact differences.
Expansion cross2(const Expansion& bx, const Expansion& by, const Expansion& cx, const Expansion& cy) {
  return sum(product(bx, cy), negate(product(by, cx)));
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Expansion bx = difference(b.x, a.x), by = difference(b.y, a.y), bz = difference(b.z, a.z);
  const Expansion cx = difference(c.x, a.x), cy = difference(c.y, a.y), cz = difference(c.z, a.z);
  const Expansion dx = difference(d.x, a.x), dy = difference(d.y, a.y), dz = difference(d.z, a.z);
  // ((b - a) x (c - a)) . (d - a)
  const Expansion nx = cross2(by, bz, cy, cz);
  const Expansion ny = cross2(bz, bx, cz, cx);
  const Expansion nz = cross2(bx, by, cx, cy);
  return sign_of(sum(sum(product(nx, dx), product(ny, dy)), product(nz, dz)));
}

}  // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Shewchuk's orient3d filter, written with d as the apex of the differences.
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  // Shewchuk's det(a,b,c,d) with d as apex equals -((b-a)x(c-a)).(d-a).
  if (std::abs(det) > kO3dErrBound * permanent) return -sign_of(det);
  return orient3d_exact(a, b, c, d);
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (bx - ax) * (cy - ay);
  const double right = (by - ay) * (cx - ax);
  const double det = left - right;
  if (std::abs(det) > kO2dErrBound * (std::abs(left) + std::abs(right))) return sign_of(det);
  const Expansion e = cross2(difference(bx, ax), difference(by, ay), difference(cx, ax), difference(cy, ay));
  return sign_of(e);
}

}  // namespace meshquilt
