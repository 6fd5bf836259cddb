#include "clip_manifest.h"

#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "util/echo.h"
#include "util/input_error.h"

namespace weft::study {
namespace {

constexpr const char* kFormat = "weft-study-clips";
constexpr int kVersion = 1;

}  // namespace

std::string clipId(Fabric fabric, bool textured) {
  return std::string(fabricName(fabric)) + (textured ? "-textured" : "-hidden");
}

nlohmann::ordered_json clipManifestJson(const ClipManifest& manifest) {
  nlohmann::ordered_json clips = nlohmann::ordered_json::array();
  for (const StudyClip& clip : manifest.clips) {
    clips.push_back({{"id", clip.id},
                     {"fabric", fabricName(clip.fabric)},
                     {"group", groupName(groupOf(clip.fabric))},
                     {"material", materialPresetOf(clip.fabric)},
                     {"textured", clip.textured},
                     {"file", clip.file},
                     {"frames", clip.frames}});
  }
  return {{"format", kFormat},
          {"version", kVersion},
          {"fps", manifest.fps},
          {"seconds_per_part", manifest.secondsPerPart},
          {"frames_per_part", manifest.framesPerPart},
          {"size", {manifest.width, manifest.height}},
          {"parts", manifest.parts},
          {"clips", clips}};
}

ClipManifest readClipManifest(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in) throw InputError(name, "", "cannot open the clip manifest (written by `weft study-videos`)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(name, "", std::string("not JSON: ") + e.what());
  }
  // Every field's type is checked by nlohmann's get<>(); its message is passed on with the path.
  const auto field = [&](const nlohmann::json& object, const char* key, const std::string& pointer) -> const nlohmann::json& {
    if (!object.is_object() || !object.contains(key)) throw InputError(name, pointer + "/" + key, "missing");
    return object.at(key);
  };
  ClipManifest manifest;
  try {
    if (field(j, "format", "").get<std::string>() != kFormat)
      throw InputError(name, "/format", std::string("expected \"") + kFormat + "\"");
    if (field(j, "version", "").get<int>() != kVersion)
      throw InputError(name, "/version", "unsupported version (this weft reads version 1)");
    manifest.fps = field(j, "fps", "").get<double>();
    manifest.secondsPerPart = field(j, "seconds_per_part", "").get<double>();
    manifest.framesPerPart = field(j, "frames_per_part", "").get<int>();
    const auto size = field(j, "size", "").get<std::vector<int>>();
    if (size.size() != 2) throw InputError(name, "/size", "expected [width, height]");
    manifest.width = size[0];
    manifest.height = size[1];
    manifest.parts = field(j, "parts", "").get<std::vector<std::string>>();
    const nlohmann::json& clips = field(j, "clips", "");
    if (!clips.is_array()) throw InputError(name, "/clips", "expected an array");
    std::set<std::string> ids;
    for (std::size_t i = 0; i < clips.size(); ++i) {
      const std::string pointer = "/clips/" + std::to_string(i);
      StudyClip clip;
      clip.id = field(clips[i], "id", pointer).get<std::string>();
      const std::string fabric = field(clips[i], "fabric", pointer).get<std::string>();
      const auto parsed = parseFabric(fabric);
      if (!parsed)
        throw InputError(name, pointer + "/fabric",
                         "unknown fabric '" + echo(fabric, 60) + "' (expected denim, t-shirt, pants or swimsuit)");
      clip.fabric = *parsed;
      clip.textured = field(clips[i], "textured", pointer).get<bool>();
      clip.file = field(clips[i], "file", pointer).get<std::string>();
      clip.frames = field(clips[i], "frames", pointer).get<int>();
      if (clip.id.empty() || clip.id.find(',') != std::string::npos)
        throw InputError(name, pointer + "/id", "a clip id must be non-empty and without commas (it goes into a CSV)");
      if (!ids.insert(clip.id).second) throw InputError(name, pointer + "/id", "clip '" + echo(clip.id, 60) + "' appears twice");
      manifest.clips.push_back(std::move(clip));
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(name, "", std::string("malformed clip manifest: ") + e.what());
  }
  return manifest;
}

}  // namespace weft::study
