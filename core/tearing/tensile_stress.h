#pragma once
// The stress that can tear (thesis §2.7, Eq. 2.60 and the sigma+ of Eq. 2.69): each triangle's
// membrane stress turned into the material frame, with its compressive part removed, so a cloth
// that is only compressed, or only moved, never tears.
#include <vector>

#include "material/elasticity.h"
#include "util/types.h"

namespace weft {

struct Cloth;
class MembraneAhead;

// The tensile part of a 2x2 symmetric stress: its eigen-decomposition with every negative
// principal stress set to zero.
Mat2 tensilePart(const Mat2& stress);

// A membrane stress (s_uu, s_vv, s_uv) in the weft/warp frame (U at weftAngleRad from material x),
// as a 2x2 tensor in the material frame (x, y of Triangle::rest).
Mat2 stressInMaterialFrame(const Vec3& stressUV, double weftAngleRad);
// The rotation from the weft/warp frame to the material frame, and the same turn with it given.
Mat2 weftToMaterial(double weftAngleRad);
Mat2 stressInMaterialFrame(const Vec3& stressUV, const Mat2& weftToMaterial);

// sigma+ of every triangle of the cloth at its current positions (N/m), in the material frame.
// `ahead` (or null): the membrane evaluated at these positions already (forces/membrane_ahead.h);
// a triangle it holds is read from it, the others evaluated.
void tensileStresses(const Cloth& cloth, const MembraneAhead* ahead, std::vector<Mat2>& outStress);
void tensileStresses(const Cloth& cloth, std::vector<Mat2>& outStress);
// The same for the listed triangles only (after a tear changed them); `ioStress` grows to the
// mesh's triangle count.
void tensileStresses(const Cloth& cloth, const std::vector<int>& triangles, std::vector<Mat2>& ioStress);

}  // namespace weft
