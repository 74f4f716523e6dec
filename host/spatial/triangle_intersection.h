#pragma once
//! Exact intersection tests between closed triangles and segments in 3D (double coordinates,
//! exact orientation predicates, so the answer is the answer for the given doubles).

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Whether closed triangles (p1, q1, r1) and (p2, q2, r2) share at least one point.
//! Guigue-Devillers (2003): only orientation predicates, coplanar triangles handled in the
//! projection onto their common plane. Touching counts as intersecting. A degenerate
//! (collinear) triangle is treated as the union of its edges.
bool triangles_intersect(const Vec3& p1, const Vec3& q1, const Vec3& r1,
                         const Vec3& p2, const Vec3& q2, const Vec3& r2);

//! Whether closed segment [a, b] meets closed non-degenerate triangle (p, q, r). Exact.
bool segment_intersects_triangle(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, const Vec3& r);

//! Whether closed segments [a, b] and [c, d] share a point (either may be a single point). Exact.
bool segments_intersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

//! Whether (a, b, c) are collinear (or coincident), exactly.
bool triangle_is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace meshquilt
