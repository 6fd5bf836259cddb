#pragma once
// Reading a scene's contact sections: "ground", "obstacles" and "contact" (scene/contact_spec.h).
// Strict like the rest of the scene format: unknown keys, wrong types and out-of-range values are
// InputErrors naming the file and the JSON pointer of the field.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/contact_spec.h"
#include "scene/scene_json_parts.h"

namespace weft {

GroundSpec parseGround(const nlohmann::json& j, const std::string& pointer, const SceneReadContext& ctx);
std::vector<ObstacleSpec> parseObstacles(const nlohmann::json& array, const std::string& pointer,
                                         const SceneReadContext& ctx);
ContactSpec parseContact(const nlohmann::json& j, const std::string& pointer, const SceneReadContext& ctx);

}  // namespace weft
