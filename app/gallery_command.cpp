// `weft gallery [--out DIR] [--width W --height H] [--quick] [--only ID,...]`: the experiments of
// the thesis' Chapter 4 (Karaoz 2015) that Weft can run, rendered headless one after the other
// (gallery/gallery_entries.h lists them). For each: DIR/ID.mp4 (every frame, through ffmpeg),
// DIR/ID.png (a contact sheet of the moments the figure shows), DIR/ID-figure.png (the figure's
// moment at full size) and a measured line, printed and written to DIR/gallery.json with the thesis' claim
// and whether the run reproduces it. The figures that need cutting are listed as not yet.
//
// As `weft study-videos`: everything that can be wrong with the input (the scenes, ffmpeg's
// presence, EGL) is checked before the first file is written; runs are deterministic.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_checks.h"
#include "command.h"
#include "contact_sheet.h"
#include "gallery/gallery_entries.h"
#include "headless_gl_context.h"
#include "mp4_encoder.h"
#include "offscreen_framebuffer.h"
#include "png_writer.h"
#include "render_view.h"
#include "scene/scene_json.h"
#include "scene_renderer.h"
#include "sim/finite_state.h"
#include "sim/world.h"
#include "util/atomic_file.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;
using gallery::GalleryEntry;
using gallery::ThesisClaim;

struct GalleryOptions {
  std::string out = "out/gallery";  // beside `weft run`'s out/SCENE; not gallery/, the sources
  int width = 960;   // of the MP4 and the figure's frame
  int height = 720;
  int sheetWidth = 1200;  // of the contact sheet (its frames are shrunk to fit)
  bool quick = false;     // a smoke run: kQuickSeconds of each scene
  std::vector<std::string> only;  // entry ids; empty for all
  bool quiet = false;
};

// --quick simulates this much of each scene (its contact-sheet times scaled to fit): enough for a
// test to see every file written and measured, not enough to reproduce anything.
constexpr double kQuickSeconds = 0.05;

fs::path sceneFile(const std::string& name) { return fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / (name + ".json"); }

// The headless renderer of the gallery: one framebuffer for every scene, torn edges in red.
struct GalleryRenderer {
  ui::HeadlessGlContext context;
  ui::OffscreenFramebuffer framebuffer;
  ui::SceneRenderer renderer;
  int width, height;

  GalleryRenderer(int w, int h) : framebuffer(w, h, 4), renderer(ui::RenderSettings{}), width(w), height(h) {}

  std::vector<std::uint8_t> draw(const World& world, const ui::OrbitCamera& camera) {
    framebuffer.bind();
    renderer.draw(ui::renderViewOf(world), camera, width, height);
    return framebuffer.readPixels();
  }
};

std::string percent(double share) {
  char text[16];
  std::snprintf(text, sizeof text, "%.0f%%", 100.0 * share);
  return text;
}

// The measured line `weft gallery` prints for an entry that ran.
std::string measuredLine(const GalleryEntry& entry, const gallery::SceneMeasure& m, const gallery::Verdict& v) {
  std::ostringstream line;
  char head[160];
  std::snprintf(head, sizeof head, "%s %s %s: %.2f m torn in %lld tears, %lld cut edges; by direction", entry.section.c_str(),
                entry.figure.c_str(), entry.id.c_str(), m.directions.total(), m.tears, m.cutEdges);
  line << head;
  for (int b = 0; b < gallery::kDirectionBins; ++b) {
    line << (b == 0 ? " " : " / ") << b * gallery::kDirectionBinDeg << ": " << percent(m.directions.share(b));
  }
  if (m.ballEnd) {
    char ball[64];
    std::snprintf(ball, sizeof ball, "; ball ends at %s = %.2f m", entry.ballAxis == 'z' ? "z" : "y",
                  entry.ballAxis == 'z' ? m.ballEnd->z() : m.ballEnd->y());
    line << ball;
  }
  line << " -- " << (v.reproduced ? "reproduced" : "NOT reproduced") << ": " << v.decidingNumber;
  return line.str();
}

nlohmann::json entryJson(const GalleryEntry& entry) {
  return {{"id", entry.id},       {"section", entry.section},        {"figure", entry.figure},
          {"title", entry.title}, {"thesis_says", entry.thesisSays}, {"scene", entry.scene}};
}

struct PlannedRun {
  const GalleryEntry* entry;
  Scene scene;
  int frames;                  // after frame 0
  std::vector<int> sheetFrames;  // frame indices of the contact sheet
  int figureFrame = 0;           // frame index of ID-figure.png
};

int writeGallery(const GalleryOptions& options) {
  std::vector<GalleryEntry> entries = gallery::galleryEntries();
  for (const std::string& id : options.only) {
    if (std::none_of(entries.begin(), entries.end(), [&](const GalleryEntry& e) { return e.id == id; })) {
      std::string known;
      for (const GalleryEntry& e : entries) known += (known.empty() ? "" : ", ") + e.id;
      std::cerr << "weft: gallery: --only: no entry '" << id << "' (the entries: " << known << ")\n";
      return kExitBadInput;
    }
  }
  auto chosen = [&](const GalleryEntry& e) {
    return options.only.empty() || std::find(options.only.begin(), options.only.end(), e.id) != options.only.end();
  };
  if (!ffmpegInstalled()) {
    std::cerr << "weft: gallery: ffmpeg is not installed (not on PATH); it encodes the videos "
                 "(apt-get install ffmpeg, or scripts/install_deps.sh)\n";
    return kExitFailure;
  }
  // Every scene loads before anything is written.
  std::vector<PlannedRun> runs;
  try {
    for (const GalleryEntry& entry : entries) {
      if (!chosen(entry) || entry.claim == ThesisClaim::NeedsCutting) continue;
      PlannedRun run{&entry, loadScene(sceneFile(entry.scene), entry.sets), 0, {}, 0};
      const double seconds = options.quick ? std::min(kQuickSeconds, entry.seconds) : entry.seconds;
      const double fps = run.scene.output.fps;
      run.frames = std::max(1, static_cast<int>(std::lround(seconds * fps)));
      auto frameAt = [&](double t) {  // --quick squeezes the entry's moments into its shorter run
        return std::clamp(static_cast<int>(std::lround(t * seconds / entry.seconds * fps)), 0, run.frames);
      };
      for (double t : entry.sheetTimes) run.sheetFrames.push_back(frameAt(t));
      run.figureFrame = frameAt(entry.figureTime);
      runs.push_back(std::move(run));
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }

  std::unique_ptr<GalleryRenderer> renderer;
  try {
    renderer = std::make_unique<GalleryRenderer>(options.width, options.height);
  } catch (const ui::GlContextError& e) {
    std::cerr << "weft: gallery: cannot start headless OpenGL: " << e.what()
              << " (needs Mesa's EGL: libegl-mesa0 and libgl1-mesa-dri)\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "weft: gallery: " << e.what() << "\n";
    return kExitFailure;
  }

  const fs::path outDir(options.out);
  nlohmann::json report = {{"thesis", "Karaoz 2015, Anisotropic tearing, Chapter 4"},
                           {"quick", options.quick},
                           {"width", options.width},
                           {"height", options.height},
                           {"direction_bins_deg", "centred on 0, 22.5, ..., 157.5 (+-11.25), material space: 0 = the "
                                                  "sheet's x (horizontal in the pictures), 90 = its y"},
                           {"entries", nlohmann::json::array()}};
  try {
    fs::create_directories(outDir);
    auto next = runs.begin();
    for (const GalleryEntry& entry : entries) {
      if (!chosen(entry)) continue;
      nlohmann::json item = entryJson(entry);
      if (entry.claim == ThesisClaim::NeedsCutting) {
        item["status"] = "not yet: needs cutting";
        if (!options.quiet) {
          std::printf("%s %s %s: not yet: needs cutting\n", entry.section.c_str(), entry.figure.c_str(), entry.id.c_str());
        }
        report["entries"].push_back(item);
        continue;
      }
      PlannedRun& run = *next++;
      World world(run.scene);
      const ui::OrbitCamera camera = ui::defaultCamera(ui::renderViewOf(world), run.scene.output.camera,
                                                       static_cast<double>(options.width) / options.height);
      const double fps = run.scene.output.fps;
      Mp4Encoder video(outDir / (entry.id + ".mp4"), options.width, options.height, fps * entry.playbackSpeed);
      std::vector<std::vector<std::uint8_t>> sheet;
      std::vector<double> sheetTimes;
      std::vector<std::uint8_t> pixels, figure;
      double figureTime = 0.0;
      const std::int64_t steps = stepsPerFrame(run.scene);
      for (int frame = 0; frame <= run.frames; ++frame) {
        if (frame > 0) {
          for (std::int64_t s = 0; s < steps; ++s) world.step();
        }
        if (!stateIsFinite(world)) {
          std::cerr << "weft: gallery: " << entry.id << ": the simulation became non-finite at t = " << world.time()
                    << " s\n";
          return kExitNonFinite;
        }
        pixels = renderer->draw(world, camera);
        video.addFrame(pixels);
        if (frame == run.figureFrame) {
          figure = pixels;
          figureTime = world.time();
        }
        for (int f : run.sheetFrames) {
          if (f == frame) {
            sheet.push_back(pixels);
            sheetTimes.push_back(world.time());
          }
        }
      }
      video.finish();
      const RgbaImage contact = contactSheet(sheet, options.width, options.height, options.sheetWidth);
      ui::writePng(outDir / (entry.id + ".png"), contact.pixels, contact.width, contact.height);
      ui::writePng(outDir / (entry.id + "-figure.png"), figure, options.width, options.height);

      const gallery::SceneMeasure measure = gallery::measureScene(world, entry.ball);
      const gallery::Verdict verdict = gallery::judge(entry, measure);
      item["status"] = verdict.reproduced ? "reproduced" : "not reproduced";
      item["deciding_number"] = verdict.decidingNumber;
      item["measure"] = gallery::sceneMeasureJson(measure);
      item["video"] = entry.id + ".mp4";
      item["video_playback_speed"] = entry.playbackSpeed;
      item["contact_sheet"] = entry.id + ".png";
      item["contact_sheet_times_s"] = sheetTimes;
      item["figure_frame"] = entry.id + "-figure.png";
      item["figure_frame_time_s"] = figureTime;
      item["sets"] = entry.sets;
      report["entries"].push_back(item);
      if (!options.quiet) {
        std::printf("%s\n", measuredLine(entry, measure, verdict).c_str());
        std::fflush(stdout);
      }
    }
    writeFileAtomically(outDir / "gallery.json", report.dump(2) + "\n");
  } catch (const std::exception& e) {
    std::cerr << "weft: gallery: " << e.what() << "\n";
    return kExitFailure;
  }
  if (!options.quiet) std::printf("wrote %s\n", (outDir / "gallery.json").string().c_str());
  return kExitOk;
}

}  // namespace

Command addGalleryCommand(CLI::App& app) {
  auto options = std::make_shared<GalleryOptions>();
  CLI::App* cli = app.add_subcommand(
      "gallery",
      "Render the thesis' Chapter 4 experiments that Weft can run (MP4, contact sheet, measured tear directions) "
      "into a folder with gallery.json; lists those that need cutting as not yet");
  cli->add_option("--out", options->out, "Output folder (default: out/gallery)");
  CLI::Option* width =
      cli->add_option("--width", options->width, "Frame width in pixels (default 960; 160 with --quick)")
          ->check(integerIn(16, 8192));
  CLI::Option* height =
      cli->add_option("--height", options->height, "Frame height in pixels (default 720; 120 with --quick)")
          ->check(integerIn(16, 8192));
  CLI::Option* sheetWidth =
      cli->add_option("--sheet-width", options->sheetWidth, "Contact sheet width in pixels (default 1200; 400 with --quick)")
          ->check(integerIn(16, 16384));
  cli->add_flag("--quick", options->quick,
                "Smoke run: 0.05 s of each scene at a tiny size (reproduces nothing; for tests)");
  cli->add_option("--only", options->only, "Only these entries (ids, comma separated)")->delimiter(',');
  cli->add_flag("--quiet,-q", options->quiet, "Print nothing but errors");
  return {cli, [options, width, height, sheetWidth] {
            // --quick is a smoke run: tiny pictures unless sizes are given.
            if (options->quick) {
              if (width->count() == 0) options->width = 160;
              if (height->count() == 0) options->height = 120;
              if (sheetWidth->count() == 0) options->sheetWidth = 400;
            }
            return writeGallery(*options);
          }};
}

}  // namespace weft::app
