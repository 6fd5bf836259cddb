#pragma once
// Signs of the orientation determinants computed exactly from double coordinates: the slow path
// behind the filtered predicates of triangle_intersection.cpp, which first try a floating-point
// estimate with an error bound and call these only when the estimate cannot decide.
//
// How: a double is a binary fraction, so differences and products of doubles can be carried
// without rounding as sums of doubles ("expansions": each two-term sum or product is split into
// its rounded value and the exact rounding error). That is exact as long as no intermediate
// product underflows or overflows, which holds for coordinates of magnitude 0 or within
// [2^-300, 2^300]; beyond that range the determinant is evaluated in GMP rationals instead.
// Coordinates must be finite.
#include "util/types.h"

namespace weft {

// Sign of det[b - a, c - a] of three points in the plane: > 0 when a, b, c turn counter-clockwise.
int exactOrient2dSign(const Vec2& a, const Vec2& b, const Vec2& c);

// Sign of det[b - a, c - a, d - a].
int exactOrient3dSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace weft
