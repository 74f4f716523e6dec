#pragma once
//! Exact orientation predicates in double precision: a floating-point filter (Shewchuk's error
//! bounds) with an exact expansion-arithmetic fallback, so the sign is always the sign of the
//! real determinant of the given double coordinates (barring overflow/underflow).

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Sign (+1, 0, -1) of det[b - a, c - a, d - a] = ((b - a) x (c - a)) . (d - a): positive when
//! d lies on the side of triangle (a, b, c) its right-hand normal points to. Exact.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

//! Sign (+1, 0, -1) of (b - a) x (c - a) for 2D points: positive when (a, b, c) turns
//! counter-clockwise. Exact.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

}  // namespace meshquilt
