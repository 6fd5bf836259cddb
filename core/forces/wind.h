#pragma once
// Wind: a per-triangle aerodynamic force from the air moving past the cloth.
//
// Each triangle is treated as a flat plate in the relative wind v = w(t) - (mean velocity of its
// corners): a drag along the normal and a lift across the wind, as in the aerodynamic cloth models
// of Keckeisen et al. 2004 ("Modelling effects of wind fields in cloth animations") and Wilson et
// al. 2014 (wind on cloth in Disney's Frozen); the exact form below is ours. With n the unit
// normal, A the current area and v_n = v . n:
//   drag  f_d = 1/2 rho C_d A  v_n |v_n|  n                      along the normal, pushing the
//                                                               cloth downwind; |f_d| ~ v_n^2
//   lift  f_l = 1/2 rho C_l A |v| v_n (n - (v_n / |v|^2) v)       perpendicular to v, in the plane
//                                                               of v and n; |f_l| = 1/2 rho C_l A
//                                                               |v|^2 sin(a) cos(a), a the angle
//                                                               of attack
// Both are unchanged when n is flipped, so the cloth is two-sided. A third of the triangle's
// force goes to each corner.
#include <vector>

#include "mesh/cloth_mesh.h"
#include "scene/scene.h"

namespace weft {

// The wind velocity at `time` (s): the steady velocity modulated by a deterministic sine gust,
// w(t) = velocity (1 + gustAmplitude sin(2 pi gustFrequency t)).
Vec3 windVelocityAt(const WindSpec& wind, double time);

// Adds the wind force on every vertex to `forces` (one entry per vertex, N).
void addWindForces(const ClothMesh& mesh, const WindSpec& wind, double time, std::vector<Vec3>& forces);

// True when there is any wind (non-zero velocity); otherwise the wind stage is skipped.
bool windEnabled(const WindSpec& wind);

}  // namespace weft
