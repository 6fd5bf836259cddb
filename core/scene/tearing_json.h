#pragma once
// Reading the scene's "tearing" object (scene/tearing_spec.h), with the same strictness as the
// rest of the scene format.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "scene/scene_json_parts.h"
#include "scene/tearing_spec.h"

namespace weft {

TearingSpec parseTearing(const nlohmann::json& j, const std::string& pointer, const SceneReadContext& ctx);

}  // namespace weft
