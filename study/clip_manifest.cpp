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
  // Each field read with its JSON pointer, so a wrong type names the field, not nlohmann's code.
  const auto field = [&](const nlohmann::json& object, const char* key, const std::string& pointer) -> const nlohmann::json& {
    if (!object.is_object() || !object.contains(key)) throw InputError(name, pointer + "/" + key, "missing");
    return object.at(key);
  };
  const auto read = [&]<typename T>(const nlohmann::json& object, const char* key, const std::string& pointer,
                                    const char* expected, T& out) {
    try {
      out = field(object, key, pointer).get<T>();
    } catch (const nlohmann::json::exception&) {
      throw InputError(name, pointer + "/" + key, std::string("expected ") + expected);
    }
  };
  ClipManifest manifest;
  std::string format;
  int version = 0;
  read(j, "format", "", "a string", format);
  if (format != kFormat) throw InputError(name, "/format", std::string("expected \"") + kFormat + "\"");
  read(j, "version", "", "an integer", version);
  if (version != kVersion) throw InputError(name, "/version", "unsupported version (this weft reads version 1)");
  read(j, "fps", "", "a number", manifest.fps);
  if (!(manifest.fps > 0.0 && manifest.fps <= 1000.0)) throw InputError(name, "/fps", "expected a number in (0, 1000]");
  read(j, "seconds_per_part", "", "a number", manifest.secondsPerPart);
  read(j, "frames_per_part", "", "an integer", manifest.framesPerPart);
  std::vector<int> size;
  read(j, "size", "", "[width, height] in pixels", size);
  if (size.size() != 2 || size[0] < 1 || size[1] < 1) throw InputError(name, "/size", "expected [width, height] in pixels");
  manifest.width = size[0];
  manifest.height = size[1];
  read(j, "parts", "", "an array of strings", manifest.parts);
  const nlohmann::json& clips = field(j, "clips", "");
  if (!clips.is_array()) throw InputError(name, "/clips", "expected an array");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < clips.size(); ++i) {
    const std::string pointer = "/clips/" + std::to_string(i);
    StudyClip clip;
    read(clips[i], "id", pointer, "a string", clip.id);
    std::string fabric;
    read(clips[i], "fabric", pointer, "a string", fabric);
    const auto parsed = parseFabric(fabric);
    if (!parsed)
      throw InputError(name, pointer + "/fabric",
                       "unknown fabric '" + echo(fabric, 60) + "' (expected denim, t-shirt, pants or swimsuit)");
    clip.fabric = *parsed;
    read(clips[i], "textured", pointer, "true or false", clip.textured);
    read(clips[i], "file", pointer, "a string", clip.file);
    read(clips[i], "frames", pointer, "an integer", clip.frames);
    if (clip.frames < 1) throw InputError(name, pointer + "/frames", "expected at least 1");
    if (clip.id.empty() || clip.id.find(',') != std::string::npos)
      throw InputError(name, pointer + "/id", "a clip id must be non-empty and without commas (it goes into a CSV)");
    if (!ids.insert(clip.id).second) throw InputError(name, pointer + "/id", "clip '" + echo(clip.id, 60) + "' appears twice");
    manifest.clips.push_back(std::move(clip));
  }
  return manifest;
}

}  // namespace weft::study
