#pragma once
// Separation strength at a vertex (Pfaff et al. 2014 as the thesis gives it, Eq. 2.69-2.71): how
// much balanced pull a candidate fracture line through the vertex would relieve.
//
// The vertex's fan of triangles is seen in material space as sectors of a circle around it, each
// with its triangle's tensile stress sigma+. A line through the vertex (for a vertex on a border or
// on an earlier tear, a ray into its fan) splits the fan into two sides. The force that side's
// material exerts on the vertex is the traction integrated over its arc,
//     q = sum over the side's sectors of sigma+_i * integral of n(theta) dtheta
//       = sum sigma+_i (g(theta_end) - g(theta_start)),   g(theta) = (sin theta, -cos theta),
// which is Eq. 2.69 with each tangent difference turned into the normal it integrates to (the
// thesis prints the tangents t_i; the traction needs the normals, as in Pfaff 2014). The two sides
// tear apart only as far as they pull in opposite directions: with q^ = unit(q1^ - q2^)
// (Eq. 2.70), zeta = min(q1 . q^, -q2 . q^) (Eq. 2.71), and zero when the sides do not pull apart
// (q1 . q2 >= 0): a rigid motion or an unbalanced load never tears.
//
// Scale: in a uniform stress sigma, a full line through an interior vertex collects the traction
// over half a circle on each side, q1 = -q2 = 2 sigma n (n the line's unit normal); a ray from a
// straight border collects it over a quarter circle on each side, once. zeta is normalized (halved
// at an interior vertex) so that it equals |sigma n|, the traction across the line, in both cases:
// a tear table's strength is then the critical traction across a line, in N/m (tear_table.h).
// ARCSim does the same (halving, then doubling at border and crack vertices).
#include <array>
#include <span>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "util/types.h"

namespace weft {

// One incident triangle's corner at the vertex.
struct FanSector {
  double start = 0.0;  // angle of the corner's first edge (rad, material space)
  double span = 0.0;   // counter-clockwise opening angle to its second edge, in (0, pi)
  Vec2 gStart = Vec2::Zero();  // g at the first and second edge (no trigonometry per line)
  Vec2 gEnd = Vec2::Zero();
  Mat2 stress = Mat2::Zero();  // the triangle's tensile stress sigma+, material frame (N/m)
};

// g(theta) = (sin theta, -cos theta), the integral of the outward normal, from the unit direction
// (cos theta, sin theta).
inline Vec2 normalIntegral(const Vec2& unitDirection) { return Vec2(unitDirection.y(), -unitDirection.x()); }

// A sector from the angles alone (tests); stressFan builds them from the edges.
FanSector makeSector(double start, double span, const Mat2& stress);

struct StressFan {
  std::vector<FanSector> sectors;
  bool closed = true;     // the sectors go all around (interior vertex)
  double openStart = 0.0;  // not closed: the fan covers [openStart, openStart + openSpan] ccw
  double openSpan = 0.0;
  // Every sector carries `uniformStress` (the vertex's averaged stress, nonlocal_stress.h). On a
  // closed fan zeta is then |S n|, the traction across the line (the scale note above), and the
  // functions below read it without the sectors: no sector edges to split at, and a bound over a
  // range of lines that is exact (separationOverPiece).
  bool uniform = false;
  Mat2 uniformStress = Mat2::Zero();
};

// Gives every sector of the fan the same stress (and marks it uniform).
void makeUniform(StressFan& fan, const Mat2& stress);
// The sectors' stresses weighted by their angles (zero for a fan without sectors).
Mat2 meanStress(const StressFan& fan);

// The fan of `vertex` (its incident triangles `around`) with the per-triangle stresses. A fan
// that does not close is open from the sector whose first edge lies on a boundary.
// The rest geometry of each triangle's three corners as fan sectors (stress left zero): it changes
// only with the topology, so it is computed once and then patched for the triangles a tear
// changes, not per step (it costs two arc tangents per corner).
using TriangleCorners = std::array<FanSector, 3>;
FanSector cornerSector(const Triangle& triangle, int corner);
void updateTriangleCorners(const ClothMesh& mesh, const std::vector<int>& triangles, std::vector<TriangleCorners>& corners);
std::vector<TriangleCorners> triangleCorners(const ClothMesh& mesh);

// `outFan` is reused (no allocation once it has grown).
void stressFan(const ClothMesh& mesh, int vertex, std::span<const int> around,
               const std::vector<TriangleCorners>& corners, const std::vector<Mat2>& triangleStress, StressFan& outFan);

// |S n| for the line at `angle` (n = -g(angle)): the traction across it, which is the separation
// strength of a closed fan read as the one stress S (makeUniform), without building the fan.
double tractionAcross(const Mat2& stress, double angle);

// zeta (N/m) for the line through the vertex at `angle` (rad, material space; for an open fan,
// the ray at `angle`, which must lie inside the fan).
double separationStrength(const StressFan& fan, double angle);

// The spectral norm of a symmetric 2x2 tensor: its largest absolute eigenvalue (for sigma+, its
// largest principal stress).
double spectralNorm(const Mat2& s);

// An upper bound of separationStrength over every line or ray: |q| of an arc is at most the
// largest principal stress times the arc's angle, and min(|q1|, |q2|) at most their mean. A vertex
// whose bound is below the weakest required strength cannot tear in any direction.
double separationStrengthBound(const StressFan& fan);

// The same bound for a closed fan given by its triangles alone (their stresses, the largest
// principal stress of each, and the vertex's corner angle in each, in the fan's order), without
// building the fan: the search screens every loaded interior vertex with it at the start of a
// step. Equal to separationStrengthBound of the fan stressFan builds from the same triangles.
double closedFanStrengthBound(std::span<const int> triangles, std::span<const double> spans,
                              const std::vector<Mat2>& stress, const std::vector<double>& largestPrincipal);

// The forces the two sides of a line (or ray) at `angle` exert on the vertex (q1, q2 above).
struct LineSides {
  Vec2 q1 = Vec2::Zero();
  Vec2 q2 = Vec2::Zero();
};
LineSides lineSides(const StressFan& fan, double angle);
// zeta from the sides' forces (Eq. 2.70-2.71, halved at an interior vertex).
double separationFromSides(const StressFan& fan, const LineSides& sides);

// How fast a side's force can change as the line turns (N/m per rad): d q1 / d theta =
// sigma(theta + pi) r(theta + pi) - sigma(theta) r(theta) for a line (r the radial unit vector),
// sigma(theta) r(theta) for a ray, so at most twice (once) the fan's largest principal stress.
double sideForceRate(const StressFan& fan);

// An upper bound of zeta over every line whose sides' forces lie within `drift` of `sides`'
// (N/m): with a = q1, b = -q2 and phi the angle between them, zeta = min(|a|, |b|) cos(phi / 2)
// (zero when phi >= 90 degrees); each side's length grows by at most drift and its direction turns
// by at most asin(drift / |side|). Tends to zeta itself as drift shrinks.
double separationBoundNear(const StressFan& fan, const LineSides& sides, double drift);

// zeta of the line at `middle`, and a bound of zeta over the lines within `halfWidth` of it
// (halfWidth <= pi / 4; for an open fan the piece must lie inside the fan). On a closed uniform fan
// the bound is the largest |S n| over the piece, exactly: |S n(theta)|^2 is a constant plus a
// sinusoid of 2 theta, whose largest value over an interval is at its peak or at an end.
// Where no sector edge lies inside the piece, each side's force is an explicit function of the
// line's angle: with Delta the turn from the middle, q(Delta) = q(0) + M (g(middle + Delta) -
// g(middle)), M a fixed sum of the sectors' stresses, and g(middle + Delta) - g(middle) =
// sin(Delta) r + (cos(Delta) - 1) g. Its length is convex in sin(Delta), so it is largest at the
// piece's ends but for the (1 - cos) term: a bound of second order in the piece's width, which
// settles the lines around a load's peak in a few pieces where the drift bound needs many.
// Otherwise `edge` is the sector edge inside (split there) and the bound is the drift's.
struct LinePieceBound {
  double zeta = 0.0;   // of the middle line
  double bound = 0.0;  // over the piece
  double edge = 0.0;   // a sector edge inside the piece (rad), NaN when there is none
};
LinePieceBound separationOverPiece(const StressFan& fan, double middle, double halfWidth);

}  // namespace weft
