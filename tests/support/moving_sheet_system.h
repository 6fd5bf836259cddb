#pragma once
// The linear system of a falling cloth, as the CG sees it: the linearized backward Euler system
// (integrate/linearized_backward_euler.cpp) of the benchmark's hanging sheet (royal-target at
// 1/60 s, presets/scenes/hanging-sheet.json) at resolution² after some steps of its fall, the
// pins constrained. Used by the multigrid's tests and by the scratch profiler
// docs/bench/amg-profile/amg_profile.cpp (which compiles moving_sheet_system.cpp beside it).
#include <Eigen/Core>

#include "integrate/system_matrix.h"

namespace weft::test {

struct ClothSystem {
  SystemMatrix A;     // pinned vertices' rows and columns replaced by identity rows
  Eigen::VectorXd b;  // right-hand side, 3 per vertex (momentum, N s)
};

// The system of step `stepsBefore` + 1 of the hanging sheet at `resolution`² vertices.
ClothSystem movingSheetSystem(int resolution, int stepsBefore);

}  // namespace weft::test
