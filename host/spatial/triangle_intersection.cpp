#include "spatial/triangle_intersection.h"

#include <algorithm>
#include <array>
#include <utility>

#include <glm/geometric.hpp>

#include "spatial/exact_predicates.h"

namespace meshquilt {
namespace {

struct P2 {
  double x, y;
};

// Projection dropping coordinate `axis`; exact, and injective on any plane not parallel to it.
P2 project(const Vec3& v, int axis) {
  switch (axis) {
    case 0: return {v.y, v.z};
    case 1: return {v.z, v.x};
    default: return {v.x, v.y};
  }
}

int orient(const P2& a, const P2& b, const P2& c) { return orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

// c lies in the bounding box of [a, b]; with orient == 0 this means c lies on the segment.
bool in_box(const P2& a, const P2& b, const P2& c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

bool segments_intersect_2d(const P2& a, const P2& b, const P2& c, const P2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && in_box(a, b, c)) return true;
  if (o2 == 0 && in_box(a, b, d)) return true;
  if (o3 == 0 && in_box(c, d, a)) return true;
  if (o4 == 0 && in_box(c, d, b)) return true;
  return false;
}

// p in closed triangle (a, b, c) of either orientation; the triangle is not degenerate.
bool point_in_triangle_2d(const P2& p, const P2& a, const P2& b, const P2& c) {
  const int s1 = orient(a, b, p), s2 = orient(b, c, p), s3 = orient(c, a, p);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

// An axis whose projection keeps triangle (a, b, c) non-degenerate; -1 when it is degenerate.
int projection_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  std::array<int, 3> axes{0, 1, 2};
  // Try the dominant normal component first (best conditioned), then the others.
  std::sort(axes.begin(), axes.end(), [&](int i, int j) { return std::abs(n[i]) > std::abs(n[j]); });
  for (int axis : axes) {
    if (orient(project(a, axis), project(b, axis), project(c, axis)) != 0) return axis;
  }
  return -1;
}

bool coplanar_triangles_intersect(const std::array<Vec3, 3>& t1, const std::array<Vec3, 3>& t2) {
  const int axis = projection_axis(t1[0], t1[1], t1[2]);
  std::array<P2, 3> a, b;
  for (int i = 0; i < 3; ++i) {
    a[i] = project(t1[i], axis);
    b[i] = project(t2[i], axis);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (segments_intersect_2d(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return true;
    }
  }
  return point_in_triangle_2d(a[0], b[0], b[1], b[2]) || point_in_triangle_2d(b[0], a[0], a[1], a[2]);
}

// The vertex alone on its side of the other triangle's plane (the others on the opposite side
// or on the plane), and whether the other triangle must be flipped to put it on the positive
// side. Preconditions: not all signs equal and non-zero, not all zero.
std::pair<int, bool> lone_vertex(const std::array<int, 3>& s) {
  for (int i = 0; i < 3; ++i) {
    if (s[i] != 0 && s[(i + 1) % 3] != s[i] && s[(i + 2) % 3] != s[i]) return {i, s[i] < 0};
  }
  // Signs (0, t, t): the triangle touches the plane at one vertex only.
  for (int i = 0; i < 3; ++i) {
    if (s[i] == 0) return {i, s[(i + 1) % 3] > 0};
  }
  return {0, false};
}

}  // namespace

bool triangle_is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
  return projection_axis(a, b, c) < 0;
}

bool segments_intersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (orient3d(a, b, c, d) != 0) return false;
  // Coplanar: project along an axis that keeps the four points' plane (or line) injective.
  const std::array<Vec3, 4> pts{a, b, c, d};
  for (int axis = 0; axis < 3; ++axis) {
    for (int i = 0; i < 4; ++i) {
      const P2 u = project(pts[i], axis), v = project(pts[(i + 1) % 4], axis), w = project(pts[(i + 2) % 4], axis);
      if (orient(u, v, w) != 0) {
        return segments_intersect_2d(project(a, axis), project(b, axis), project(c, axis), project(d, axis));
      }
    }
  }
  // All four points collinear (or coincident): any projection that does not collapse the line.
  for (int axis = 0; axis < 3; ++axis) {
    const P2 p0 = project(a, axis);
    for (const Vec3& v : pts) {
      const P2 pv = project(v, axis);
      if (pv.x != p0.x || pv.y != p0.y) {
        return segments_intersect_2d(p0, project(b, axis), project(c, axis), project(d, axis));
      }
    }
  }
  return a == c;  // all four points coincide
}

bool segment_intersects_triangle(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, const Vec3& r) {
  const int sa = orient3d(p, q, r, a), sb = orient3d(p, q, r, b);
  if (sa * sb > 0) return false;
  if (sa == 0 && sb == 0) {
    const int axis = projection_axis(p, q, r);
    const P2 pa = project(a, axis), pb = project(b, axis);
    const P2 pp = project(p, axis), pq = project(q, axis), pr = project(r, axis);
    return point_in_triangle_2d(pa, pp, pq, pr) || segments_intersect_2d(pa, pb, pp, pq) ||
           segments_intersect_2d(pa, pb, pq, pr) || segments_intersect_2d(pa, pb, pr, pp);
  }
  // The segment crosses or touches the plane at one point: it is inside the triangle when the
  // line through a, b passes all three edges on the same side.
  const int s1 = orient3d(a, b, p, q), s2 = orient3d(a, b, q, r), s3 = orient3d(a, b, r, p);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

bool triangles_intersect(const Vec3& p1, const Vec3& q1, const Vec3& r1,
                         const Vec3& p2, const Vec3& q2, const Vec3& r2) {
  const bool degenerate1 = triangle_is_degenerate(p1, q1, r1);
  const bool degenerate2 = triangle_is_degenerate(p2, q2, r2);
  if (degenerate1 || degenerate2) {
    const std::array<Vec3, 3> t1{p1, q1, r1}, t2{p2, q2, r2};
    for (int i = 0; i < 3; ++i) {
      if (degenerate1 && degenerate2) {
        for (int j = 0; j < 3; ++j) {
          if (segments_intersect(t1[i], t1[(i + 1) % 3], t2[j], t2[(j + 1) % 3])) return true;
        }
      } else if (degenerate1) {
        if (segment_intersects_triangle(t1[i], t1[(i + 1) % 3], p2, q2, r2)) return true;
      } else {
        if (segment_intersects_triangle(t2[i], t2[(i + 1) % 3], p1, q1, r1)) return true;
      }
    }
    return false;
  }

  std::array<int, 3> s1{orient3d(p2, q2, r2, p1), orient3d(p2, q2, r2, q1), orient3d(p2, q2, r2, r1)};
  if ((s1[0] > 0 && s1[1] > 0 && s1[2] > 0) || (s1[0] < 0 && s1[1] < 0 && s1[2] < 0)) return false;
  std::array<Vec3, 3> a{p1, q1, r1}, b{p2, q2, r2};
  if (s1[0] == 0 && s1[1] == 0 && s1[2] == 0) return coplanar_triangles_intersect(a, b);
  std::array<int, 3> s2{orient3d(p1, q1, r1, p2), orient3d(p1, q1, r1, q2), orient3d(p1, q1, r1, r2)};
  if ((s2[0] > 0 && s2[1] > 0 && s2[2] > 0) || (s2[0] < 0 && s2[1] < 0 && s2[2] < 0)) return false;

  // Canonical form: a[0] alone on the positive side of b's plane, b[0] alone on the positive
  // side of a's plane. Cyclic rotations keep a plane's orientation, swapping two vertices flips it.
  const auto [i, flip_b] = lone_vertex(s1);
  std::rotate(a.begin(), a.begin() + i, a.end());
  if (flip_b) {
    std::swap(b[1], b[2]);
    std::swap(s2[1], s2[2]);
  }
  const auto [j, flip_a] = lone_vertex(s2);
  std::rotate(b.begin(), b.begin() + j, b.end());
  if (flip_a) std::swap(a[1], a[2]);

  // Both triangles cut the line L of the planes' intersection in an interval; the intervals
  // overlap exactly when these two orientations allow it (Guigue-Devillers, Section 3).
  return orient3d(a[0], a[1], b[0], b[1]) <= 0 && orient3d(a[0], a[2], b[2], b[0]) <= 0;
}

}  // namespace meshquilt
