// `weft study-videos [--out DIR]`: the clips of the thesis' user study (§3.4): for each of its four
// fabrics one clip of three parts, wind (presets/scenes/study-wind.json), moved left and right by
// its pins (study-moved-by-pins.json) and torn by a heavy ball (study-ball-tear.json), each part
// simulated with the fabric's material. Every clip is encoded twice from the same simulation,
// textured and with the texture hidden (study_clip_look.h), as DIR/FABRIC-textured.mp4 and
// DIR/FABRIC-hidden.mp4, and DIR/manifest.json lists them (study/clip_manifest.h) for `weft guess`.
//
// The simulation is deterministic and so is the encoding (mp4_encoder.h): the same command gives
// the same files. Everything that can be wrong with the input (the part scenes, the materials,
// ffmpeg's presence, EGL) is checked before the first file is written.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_checks.h"
#include "command.h"
#include "headless_gl_context.h"
#include "mp4_encoder.h"
#include "offscreen_framebuffer.h"
#include "render_view.h"
#include "scene/scene_json.h"
#include "scene_renderer.h"
#include "sim/finite_state.h"
#include "sim/world.h"
#include "study/clip_manifest.h"
#include "study_clip_look.h"
#include "util/atomic_file.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

// The parts of every clip, in playing order; presets/scenes/NAME.json.
const std::vector<std::string> kParts{"study-wind", "study-moved-by-pins", "study-ball-tear"};

struct StudyVideosOptions {
  std::string out = "study-clips";
  double secondsPerPart = 5.0;  // thesis §3.4: 15 s clips of three 5 s parts
  int width = 960;
  int height = 720;
  bool quiet = false;
};

fs::path partScene(const std::string& part) { return fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / (part + ".json"); }

// The part's scene with the fabric's material on its cloth.
Scene loadPart(const std::string& part, study::Fabric fabric) {
  return loadScene(partScene(part), {"cloths.0.material=" + std::string(study::materialPresetOf(fabric))});
}

// The headless renderer both looks of a clip are drawn with: one framebuffer, one camera per part.
struct ClipRenderer {
  ui::HeadlessGlContext context;
  ui::OffscreenFramebuffer framebuffer;
  ui::SceneRenderer renderer;
  int width, height;

  ClipRenderer(int w, int h) : framebuffer(w, h, 4), renderer(studySettings()), width(w), height(h) {}

  static ui::RenderSettings studySettings() {
    ui::RenderSettings settings;
    settings.markTornAndCutEdges = false;
    return settings;
  }

  std::vector<std::uint8_t> draw(const World& world, const ui::OrbitCamera& camera, study::Fabric fabric,
                                 bool textured) {
    ui::RenderView view = ui::renderViewOf(world);
    dressForStudy(view, fabric, textured);
    framebuffer.bind();
    renderer.draw(view, camera, width, height);
    return framebuffer.readPixels();
  }
};

int writeStudyVideos(const StudyVideosOptions& options) {
  if (!ffmpegInstalled()) {
    std::cerr << "weft: study-videos: ffmpeg is not installed (not on PATH); it encodes the clips "
                 "(apt-get install ffmpeg, or scripts/install_deps.sh)\n";
    return kExitFailure;
  }
  // Every part scene of every fabric loads before anything starts.
  std::vector<std::vector<Scene>> scenes;  // [fabric][part]
  try {
    for (study::Fabric fabric : study::kFabrics) {
      scenes.emplace_back();
      for (const std::string& part : kParts) scenes.back().push_back(loadPart(part, fabric));
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
  study::ClipManifest manifest;
  manifest.fps = scenes[0][0].output.fps;
  for (const auto& parts : scenes) {
    for (const Scene& scene : parts) {
      if (scene.output.fps != manifest.fps) {
        std::cerr << "weft: " << scene.file.string() << ": /output/fps: the study's parts must share one frame rate ("
                  << manifest.fps << ")\n";
        return kExitBadInput;
      }
    }
  }
  manifest.secondsPerPart = options.secondsPerPart;
  manifest.framesPerPart = std::max(1, static_cast<int>(std::lround(options.secondsPerPart * manifest.fps)));
  manifest.width = options.width;
  manifest.height = options.height;
  manifest.parts = kParts;

  std::unique_ptr<ClipRenderer> clipRenderer;
  try {
    clipRenderer = std::make_unique<ClipRenderer>(options.width, options.height);
  } catch (const ui::GlContextError& e) {
    std::cerr << "weft: study-videos: cannot start headless OpenGL: " << e.what()
              << " (needs Mesa's EGL: libegl-mesa0 and libgl1-mesa-dri)\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "weft: study-videos: " << e.what() << "\n";
    return kExitFailure;
  }

  const fs::path outDir(options.out);
  try {
    fs::create_directories(outDir);
    for (std::size_t f = 0; f < study::kFabrics.size(); ++f) {
      const study::Fabric fabric = study::kFabrics[f];
      const std::string texturedId = study::clipId(fabric, true), hiddenId = study::clipId(fabric, false);
      Mp4Encoder textured(outDir / (texturedId + ".mp4"), options.width, options.height, manifest.fps);
      Mp4Encoder hidden(outDir / (hiddenId + ".mp4"), options.width, options.height, manifest.fps);
      for (std::size_t p = 0; p < kParts.size(); ++p) {
        const Scene& scene = scenes[f][p];
        if (!options.quiet) {
          std::printf("%s: %s, %d frames\n", std::string(study::fabricName(fabric)).c_str(), kParts[p].c_str(),
                      manifest.framesPerPart);
          std::fflush(stdout);
        }
        World world(scene);
        const ui::OrbitCamera camera = ui::defaultCamera(ui::renderViewOf(world), scene.output.camera,
                                                         static_cast<double>(options.width) / options.height);
        const std::int64_t steps = stepsPerFrame(scene);
        for (int frame = 0; frame < manifest.framesPerPart; ++frame) {
          if (frame > 0) {
            for (std::int64_t s = 0; s < steps; ++s) world.step();
          }
          if (!stateIsFinite(world)) {
            std::cerr << "weft: study-videos: " << study::fabricName(fabric) << ", " << kParts[p]
                      << ": the simulation became non-finite at t = " << world.time() << " s; no clip written\n";
            return kExitNonFinite;
          }
          textured.addFrame(clipRenderer->draw(world, camera, fabric, true));
          hidden.addFrame(clipRenderer->draw(world, camera, fabric, false));
        }
      }
      textured.finish();
      hidden.finish();
      const int frames = manifest.framesPerPart * static_cast<int>(kParts.size());
      manifest.clips.push_back({texturedId, fabric, true, texturedId + ".mp4", frames});
      manifest.clips.push_back({hiddenId, fabric, false, hiddenId + ".mp4", frames});
      if (!options.quiet) {
        std::printf("wrote %s and %s\n", textured.file().string().c_str(), hidden.file().string().c_str());
      }
    }
    writeFileAtomically(outDir / "manifest.json", study::clipManifestJson(manifest).dump(2) + "\n");
  } catch (const std::exception& e) {
    std::cerr << "weft: study-videos: " << e.what() << "\n";
    return kExitFailure;
  }
  if (!options.quiet) std::printf("wrote %s\n", (outDir / "manifest.json").string().c_str());
  return kExitOk;
}

}  // namespace

Command addStudyVideosCommand(CLI::App& app) {
  auto options = std::make_shared<StudyVideosOptions>();
  CLI::App* cli = app.add_subcommand(
      "study-videos",
      "Render the user study's clips (thesis §3.4): four fabrics in wind, moved by pins and torn by a ball; "
      "textured and texture-hidden MP4s (ffmpeg) and manifest.json");
  cli->add_option("--out", options->out, "Output folder (default: study-clips)");
  cli->add_option("--seconds-per-part", options->secondsPerPart, "Seconds of each of the three parts (default 5)")
      ->check(numberIn(0.01, 60.0));
  cli->add_option("--width", options->width, "Frame width in pixels (default 960)")->check(integerIn(16, 8192));
  cli->add_option("--height", options->height, "Frame height in pixels (default 720)")->check(integerIn(16, 8192));
  cli->add_flag("--quiet,-q", options->quiet, "Print nothing but errors");
  return {cli, [options] { return writeStudyVideos(*options); }};
}

}  // namespace weft::app
