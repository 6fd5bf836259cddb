#pragma once
// The CG preconditioners' names as the scene file spells them (scene_json.cpp reads them), for
// every place that writes or lists them: metrics.json, the editor's Solver panel.
#include <array>

#include "scene/scene.h"

namespace weft {

// In the order the editor lists them: the default first.
inline constexpr std::array<PreconditionerKind, 4> kPreconditioners = {
    PreconditionerKind::Amg, PreconditionerKind::LaggedCholesky, PreconditionerKind::LaggedExactCholesky,
    PreconditionerKind::BlockJacobi};

const char* preconditionerName(PreconditionerKind kind);

}  // namespace weft
