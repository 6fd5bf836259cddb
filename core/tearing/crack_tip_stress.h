#pragma once
// Where and whether a crack runs on from its tip: the traction averaged over a fixed length of
// material ahead of the tip (the average stress criterion of Whitney & Nuismer 1974, "Stress
// fracture criteria for laminated composites containing stress concentrations", J. Composite
// Materials 8: a notched laminate fails when the stress averaged over a characteristic distance
// a0 ahead of the notch reaches the unnotched strength).
//
// Why not the tip's own fan, as at any other vertex: at a tip the stress is singular (it grows as
// 1/sqrt(r) towards the tip), so the fan's triangles read a stress that grows as the mesh is
// refined, and a crack ran faster on finer meshes; and the fan's few triangles each see a
// different part of the singular field, so the best ray swung by 20-40 degrees from tear to tear
// on an isotropic table and cracks wandered and split. The average of the traction along a
// segment of fixed material length converges as the mesh is refined (the singularity is
// integrable), and it is smooth in the ray's direction: a mode I crack runs straight on.
//
// For a ray at angle theta from the tip, with n its unit normal:
//     t(theta) = (1/L) * integral over s in [0, L] of sigma+(tip + s d(theta)) n ds   (N/m),
// the mean traction across the prospective crack (sigma+ piecewise constant per triangle, so the
// integral is a sum over the triangles the segment crosses); omega = |t| / (f R(alpha)), with f
// the table's propagation factor. |t| is what the separation strength reads in a uniform stress
// (separation_strength.h), so a table's strengths mean the same at a tip as anywhere else. A
// segment that reaches a border (the sheet's edge, another crack) is averaged over the length it
// covers.
#include <vector>

#include "mesh/cloth_mesh.h"
#include "tearing/tear_candidates.h"
#include "tearing/tear_table.h"
#include "tearing/vertex_fan.h"
#include "util/types.h"

namespace weft {

// The mean traction across the ray from `vertex` along the unit `direction` (material space),
// over `length` metres of material; zero when the ray points out of the vertex's fan.
// `fan` is walkFan of the vertex.
Vec2 meanTractionAhead(const ClothMesh& mesh, const VertexFan& fan, const std::vector<Mat2>& triangleStress,
                       const Vec2& direction, double length);

// The best ray from a crack tip by the average stress criterion (angle, separation = |t|,
// required, alpha, omega filled; the caller fills vertex and position), sampling `samples`
// directions over the open fan and refining the best.
TearCandidate bestTipLine(const ClothMesh& mesh, const VertexFan& fan, const std::vector<Mat2>& triangleStress,
                          const TearTable& table, double weftAngleRad, const StrengthScale& strengthScale, double length,
                          int samples);

// Every ray from the tip with omega > 1 at a local maximum of the sampling, best first.
std::vector<TearCandidate> tipLinesAboveOne(const ClothMesh& mesh, const VertexFan& fan,
                                            const std::vector<Mat2>& triangleStress, const TearTable& table,
                                            double weftAngleRad, const StrengthScale& strengthScale, double length, int samples);

}  // namespace weft
