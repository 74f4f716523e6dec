#include "spatial/exact_predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshquilt {
namespace {

// Expansions (Shewchuk 1997): sums of non-overlapping doubles in increasing magnitude, so the
// sign of the sum is the sign of the last component (zeros are eliminated). Fixed capacity on
// the stack: flat and near-flat meshes send many tests here, so no heap allocation.
template <int N>
struct Expansion {
  double v[N];
  int n = 0;
};

constexpr double kEpsilon = std::numeric_limits<double>::epsilon() / 2.0;  // 2^-53
constexpr double kO3dErrBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
constexpr double kO2dErrBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

// a - b exactly, as one or two components.
inline Expansion<2> difference(double a, double b) {
  double x, y;
  two_sum(a, -b, x, y);
  Expansion<2> e;
  if (y != 0.0) e.v[e.n++] = y;
  e.v[e.n++] = x;
  return e;
}

// Fast-Expansion-Sum with zero elimination: merge by magnitude, then accumulate.
template <int A, int B>
Expansion<A + B> add(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<A + B> h;
  int i = 0, j = 0;
  auto next = [&]() {
    if (j >= f.n || (i < e.n && std::abs(e.v[i]) < std::abs(f.v[j]))) return e.v[i++];
    return f.v[j++];
  };
  double q = next();
  while (i < e.n || j < f.n) {
    double sum, err;
    two_sum(q, next(), sum, err);
    if (err != 0.0) h.v[h.n++] = err;
    q = sum;
  }
  if (q != 0.0 || h.n == 0) h.v[h.n++] = q;
  return h;
}

// Scale-Expansion with zero elimination.
template <int A>
Expansion<2 * A> scale(const Expansion<A>& e, double b) {
  Expansion<2 * A> h;
  double q, hh;
  two_product(e.v[0], b, q, hh);
  if (hh != 0.0) h.v[h.n++] = hh;
  for (int i = 1; i < e.n; ++i) {
    double p1, p0, sum, err;
    two_product(e.v[i], b, p1, p0);
    two_sum(q, p0, sum, err);
    if (err != 0.0) h.v[h.n++] = err;
    two_sum(p1, sum, q, err);
    if (err != 0.0) h.v[h.n++] = err;
  }
  if (q != 0.0 || h.n == 0) h.v[h.n++] = q;
  return h;
}

// Product of an expansion and a two-component expansion.
template <int A>
Expansion<4 * A> multiply(const Expansion<A>& e, const Expansion<2>& f) {
  if (f.n == 1) {
    const Expansion<2 * A> s = scale(e, f.v[0]);
    Expansion<4 * A> h;
    h.n = s.n;
    std::copy(s.v, s.v + s.n, h.v);
    return h;
  }
  return add(scale(e, f.v[0]), scale(e, f.v[1]));
}

template <int A>
Expansion<A> negate(Expansion<A> e) {
  for (int i = 0; i < e.n; ++i) e.v[i] = -e.v[i];
  return e;
}

template <int A>
int sign_of(const Expansion<A>& e) {
  const double top = e.v[e.n - 1];
  return (top > 0.0) - (top < 0.0);
}

inline int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

// b_x c_y - b_y c_x of exact differences.
Expansion<16> cross2(const Expansion<2>& bx, const Expansion<2>& by, const Expansion<2>& cx, const Expansion<2>& cy) {
  return add(multiply(bx, cy), negate(multiply(by, cx)));
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Expansion<2> bx = difference(b.x, a.x), by = difference(b.y, a.y), bz = difference(b.z, a.z);
  const Expansion<2> cx = difference(c.x, a.x), cy = difference(c.y, a.y), cz = difference(c.z, a.z);
  const Expansion<2> dx = difference(d.x, a.x), dy = difference(d.y, a.y), dz = difference(d.z, a.z);
  // ((b - a) x (c - a)) . (d - a)
  const Expansion<16> nx = cross2(by, bz, cy, cz);
  const Expansion<16> ny = cross2(bz, bx, cz, cx);
  const Expansion<16> nz = cross2(bx, by, cx, cy);
  return sign_of(add(add(multiply(nx, dx), multiply(ny, dy)), multiply(nz, dz)));
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
  // A zero permanent means every product has an exactly zero difference (equal coordinates,
  // as in axis-aligned flat meshes): the determinant is exactly zero.
  if (permanent == 0.0) return 0;
  return orient3d_exact(a, b, c, d);
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (bx - ax) * (cy - ay);
  const double right = (by - ay) * (cx - ax);
  const double det = left - right;
  const double permanent = std::abs(left) + std::abs(right);
  if (std::abs(det) > kO2dErrBound * permanent) return sign_of(det);
  if (permanent == 0.0) return 0;
  return sign_of(cross2(difference(bx, ax), difference(by, ay), difference(cx, ax), difference(cy, ay)));
}

}  // namespace meshquilt
