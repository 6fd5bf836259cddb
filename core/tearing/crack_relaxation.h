#pragma once
// Local relaxation after a tear (Pfaff et al. 2014, §6, and ARCSim's local_physics_step): the
// stress a crack sheds flows to its tip long before the next step's global solve shows it. To
// decide within the step whether the crack runs on, the vertices within a few rings of the new
// crack ends are relaxed towards membrane equilibrium with the ring around them held, and the
// tensile stress of their triangles is read at the relaxed positions. The positions themselves are
// then put back (as ARCSim rewinds): the relaxation only tells where the stress went, and the
// next step's dynamics move the cloth.
//
// The solver is nonlinear Gauss-Seidel: each free vertex in turn takes the Newton step of its own
// 3x3 block (the definite membrane Hessian's diagonal block), halved until its own energy falls, so
// the patch's energy never rises (a plain Jacobi sweep was measured to diverge on the stiff,
// strain-stiffening measured fabrics, and to tear the sheet to pieces with its false stresses).
#include <vector>

#include "util/types.h"

namespace weft {

struct Cloth;

struct CrackRelaxationSettings {
  int rings = 2;   // vertices within this many edges of a crack end move; the next ring is held
  int sweeps = 6;  // Jacobi sweeps over the patch
};

// Relaxes around `crackEnds` and writes the tensile stress (material frame, N/m, as
// tensileStresses gives it) of every patch triangle into `ioStress` (indexed by triangle, sized to
// the mesh). Returns the patch's triangles, sorted. The cloth's positions are unchanged on return.
std::vector<int> relaxAroundCrack(Cloth& cloth, const std::vector<int>& crackEnds,
                                  const CrackRelaxationSettings& settings, std::vector<Mat2>& ioStress);

}  // namespace weft
