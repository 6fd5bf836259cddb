#pragma once
// The list of the user study's clips that `weft study-videos` writes next to them (manifest.json)
// and `weft guess` reads: which fabric each clip shows, whether its texture is shown, its file.
//
//   {"format": "weft-study-clips", "version": 1, "fps": 30, "seconds_per_part": 5,
//    "frames_per_part": 150, "size": [960, 720],
//    "parts": ["study-wind", "study-moved-by-pins", "study-ball-tear"],
//    "clips": [{"id": "denim-textured", "fabric": "denim", "group": "stiff",
//               "material": "11oz-black-denim", "textured": true,
//               "file": "denim-textured.mp4", "frames": 450}, ...]}
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fabric.h"

namespace weft::study {

struct StudyClip {
  std::string id;          // the clip column of the answers file, e.g. "denim-hidden"
  Fabric fabric = Fabric::Denim;
  bool textured = true;    // false: one neutral colour, no weave (the "guess the fabric" clips)
  std::string file;        // the MP4, relative to the manifest's folder
  int frames = 0;          // video frames in the file
};

struct ClipManifest {
  double fps = 30.0;                // video frames per second (= simulated frames per second)
  double secondsPerPart = 5.0;      // s of each part
  int framesPerPart = 150;          // round(fps * secondsPerPart), at least 1
  int width = 960, height = 720;    // px of the rendered frames
  std::vector<std::string> parts;   // the scenes of the parts, in playing order
  std::vector<StudyClip> clips;     // fabric by fabric, textured before hidden
};

// "denim-textured", "t-shirt-hidden": the id (and, with ".mp4", the file) of a fabric's clip.
std::string clipId(Fabric fabric, bool textured);

nlohmann::ordered_json clipManifestJson(const ClipManifest& manifest);
// Reads DIR/manifest.json, as written by clipManifestJson. Throws InputError naming the file and
// the field for anything malformed, unknown or missing.
ClipManifest readClipManifest(const std::filesystem::path& file);

}  // namespace weft::study
