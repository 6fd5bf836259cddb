// `weft run SCENE`: simulate a scene headless and write metrics.json (and OBJ frames with --obj,
// PNG frames rendered through EGL with --png, an MP4 of them with --video).
//
// Order matters for what a failure leaves behind: everything that can be wrong with the input
// (scene, presets, meshes, pins) is checked by loading the scene and building the World before
// the output folder is created, so bad input never leaves an empty or stale-looking result.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "util/atomic_file.h"
#include "cli_checks.h"
#include "command.h"
#include "run_command.h"
#include "contact/obstacle.h"
#include "frame_obj_writer.h"
#include "frame_png_writer.h"
#include "headless_gl_context.h"
#include "metrics_writer.h"
#include "progress_bar.h"
#include "scene/scene_json.h"
#include "scene/scene_limits.h"
#include "sim/finite_state.h"
#include "sim/health_check.h"
#include "run_estimate.h"
#include "staged_output.h"
#include "sim/world.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

void writeFrames(const World& world, const fs::path& framesDir, int frame) {
  const bool several = world.clothCount() > 1;
  for (int i = 0; i < world.clothCount(); ++i) {
    const std::string& name = world.scene().cloths[static_cast<std::size_t>(i)].name;
    char comment[160];
    std::snprintf(comment, sizeof comment, "weft: scene %s, cloth %s, frame %d, t = %.6f s",
                  world.scene().name.c_str(), name.c_str(), frame, world.time());
    writeFileAtomically(frameObjPath(framesDir, frame, name, several), clothToObj(world.cloth(i), comment));
  }
  for (int i = 0; i < world.obstacleCount(); ++i) {
    const Obstacle& obstacle = world.obstacle(i);
    char comment[160];
    std::snprintf(comment, sizeof comment, "weft: scene %s, obstacle %s, frame %d, t = %.6f s",
                  world.scene().name.c_str(), obstacle.name.c_str(), frame, world.time());
    writeFileAtomically(obstacleObjPath(framesDir, frame, obstacle.name),
                        obstacleToObj(world.obstacleVertices(i), obstacle.topology.triangles, comment));
  }
}

void printStageShares(const StageProfile& profile) {
  double total = 0.0;
  for (double ms : profile.totalMs) total += ms;
  std::printf("%-24s %12s %8s\n", "stage", "total ms", "share");
  for (std::size_t k = 0; k < profile.names.size(); ++k) {
    const double share = total > 0.0 ? 100.0 * profile.totalMs[k] / total : 0.0;
    std::printf("%-24s %12.2f %7.1f%%\n", profile.names[k].c_str(), profile.totalMs[k], share);
  }
}

}  // namespace

int runScene(const RunOptions& options) {
  // --frames and --threads are shorthands for overrides, applied after the user's --set so that
  // the explicit flag wins.
  std::vector<std::string> overrides = options.overrides;
  if (options.frames) overrides.push_back("output.frames=" + std::to_string(*options.frames));
  if (options.threads) overrides.push_back("solver.threads=" + std::to_string(*options.threads));

  std::optional<Scene> scene;
  std::unique_ptr<World> world;
  try {
    scene = loadScene(options.scene, overrides);
    // Results do not depend on the thread count (determinism), so more threads than the machine
    // can run at once only cost, and a lot: the solver's threads wait for each other many times a
    // step, and one without a core of its own keeps the others waiting (measured on 2 cores,
    // 3 threads: a 64² tearing step's linear solve 14 -> 232 ms).
    const int machineThreads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (scene->solver.threads > machineThreads) {
      std::cerr << "weft: solver.threads = " << scene->solver.threads << " is more than the " << machineThreads
                << " hardware thread(s) of this machine, which only slows the run; using " << machineThreads
                << " (same results)\n";
      scene->solver.threads = machineThreads;
    }
    world = std::make_unique<World>(*scene);
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }

  const fs::path outDir = options.out.empty() ? fs::path("out") / scene->name : fs::path(options.out);
  // Everything is written into a staging folder and moved into outDir at the end (staged_output.h).
  std::unique_ptr<StagedOutput> staged;
  fs::path stagingDir;
  fs::path framesDir;
  const bool png = options.png || options.video;
  int width = 0, height = 0;
  if (png && !parseImageSize(options.size, width, height)) {
    std::cerr << "weft: --size: '" << options.size << "' is not WxH with both between 16 and 8192\n";
    return kExitBadInput;
  }
  // EGL starts before anything is written, so a machine that cannot render leaves no output.
  std::unique_ptr<FramePngWriter> pngWriter;
  if (png) {
    try {
      pngWriter = std::make_unique<FramePngWriter>(*world, width, height);
    } catch (const ui::GlContextError& e) {
      std::cerr << "weft: --png: cannot start headless OpenGL: " << e.what()
                << " (needs Mesa's EGL: libegl-mesa0 and libgl1-mesa-dri)\n";
      return kExitFailure;
    } catch (const std::exception& e) {
      std::cerr << "weft: --png: " << e.what() << "\n";
      return kExitFailure;
    }
  }
  const bool video = options.video && onPath("ffmpeg");
  if (options.video && !video) {
    std::cerr << "weft: --video: ffmpeg is not installed (not on PATH); writing the PNG frames only "
                 "(apt-get install ffmpeg to get frames.mp4)\n";
  }
  int pngFrames = 0;
  auto writeImages = [&](int frame) {
    if (!pngWriter || frame % options.every != 0) return;
    pngWriter->write(*world, framesDir, frame);
    ++pngFrames;
  };

  const int frames = scene->output.frames;
  const std::int64_t stepsPerFrameCount = stepsPerFrame(*scene);
  const bool talk = !options.quiet;

  // A long run says so before it starts, even with --quiet (one line on stderr).
  std::int64_t vertexCount = 0;
  for (int i = 0; i < world->clothCount(); ++i) vertexCount += world->cloth(i).vertexCount();
  const double estimate =
      estimatedRunSeconds(vertexCount, scene->solver.substeps, static_cast<std::int64_t>(frames) * stepsPerFrameCount);
  bool announced = estimate > kLongRunSeconds;
  if (announced) {
    std::cerr << "weft: a long run: " << frames << " frames x " << stepsPerFrameCount << " steps x "
              << scene->solver.substeps << " substep(s) of " << vertexCount << " cloth vertices, roughly "
              << describeDuration(estimate) << " (estimated; fewer frames, a coarser mesh or a larger solver.dt shorten it)\n";
  }

  if (talk) {
    std::printf("scene %s: %d frames x %lld steps of %g s, %d substep(s), %d thread(s)\n", scene->name.c_str(), frames,
                static_cast<long long>(stepsPerFrameCount), scene->solver.dt, scene->solver.substeps, scene->solver.threads);
    std::printf("stages:");
    for (const auto& stage : world->stagesRun()) std::printf(" %s", stage.c_str());
    std::printf("\n");
    std::fflush(stdout);
  }

  try {
    staged = std::make_unique<StagedOutput>(outDir);
    stagingDir = staged->staging();
    framesDir = stagingDir / "frames";
    if (options.obj || png) fs::create_directories(framesDir);
    if (options.obj) writeFrames(*world, framesDir, 0);
    if (png) writeImages(0);
  } catch (const std::exception& e) {
    std::cerr << "weft: cannot write to " << outDir.string() << ": " << e.what() << "\n";
    return kExitFailure;
  }

  ProgressBar progress(frames, "frames", talk && ProgressBar::stderrIsTerminal());
  double wallSeconds = 0.0;
  bool finite = stateIsFinite(*world);
  int framesDone = 0;
  HealthCheck health(*world, stepsPerFrameCount);
  // An unhealthy state is reported once; without --keep-going the run stops at the step it failed.
  bool warned = false;
  auto reportUnhealthy = [&] {
    if (warned || health.healthy()) return;
    warned = true;
    const HealthFailure& failure = *health.failure();
    progress.finish();
    std::cerr << "weft: " << (options.keepGoing ? "warning: " : "") << healthWarning(failure)
              << (options.keepGoing ? " (continuing: --keep-going)" : "") << "\n";
  };
  try {
    for (int frame = 1; frame <= frames && finite && (health.healthy() || options.keepGoing); ++frame) {
      const auto start = std::chrono::steady_clock::now();
      bool stop = false;
      for (std::int64_t s = 0; s < stepsPerFrameCount && !stop; ++s) {
        world->step();
        stop = !health.afterStep(*world) && !options.keepGoing;
      }
      wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // A non-finite state only gets worse; stop, but still report what happened.
      finite = stateIsFinite(*world);
      reportUnhealthy();
      if (finite && !stop) {
        framesDone = frame;
        if (options.obj) writeFrames(*world, framesDir, frame);
        writeImages(frame);
      }
      progress.update(frame);
      // The first frame's time is a better guide than the count: say so if the estimate missed.
      const double projected = wallSeconds * frames / frame;
      const bool continues = finite && !stop && frames > 1;
      if (frame == 1 && !announced && projected > kLongRunSeconds && continues) {
        announced = true;
        progress.finish();
        std::cerr << "weft: a long run: the first frame took " << describeDuration(wallSeconds) << ", so " << frames
                  << " frames will take about " << describeDuration(projected) << "\n";
      }
    }
    if (finite) health.checkNow(*world);
    reportUnhealthy();
    progress.finish();

    const fs::path metricsFile = outDir / "metrics.json";
    nlohmann::ordered_json metrics = runMetrics(*world, wallSeconds);
    metrics["healthy"] = health.healthy() && finite;
    if (const auto& failure = health.failure()) {
      metrics["health"] = {{"first_failing_step", failure->step}, {"time_s", failure->time},
                           {"check", failure->check},            {"stage", failure->stage},
                           {"value", failure->value},            {"limit", failure->limit},
                           {"message", failure->message}};
    }
    if (pngWriter) {
      metrics["render"] = {{"gl_renderer", pngWriter->glRenderer()},
                           {"size", {pngWriter->width(), pngWriter->height()}},
                           {"frames", pngFrames}};
    }
    const fs::path videoFile = outDir / "frames.mp4";
    bool videoWritten = false;
    if (video) {
      const double fps = scene->output.fps / options.every;
      videoWritten = encodeVideo(framesDir, stagingDir / "frames.mp4", fps) == 0;
    }
    writeFileAtomically(stagingDir / "metrics.json", metrics.dump(2) + "\n");
    staged->publish(options.obj, png);
    const fs::path publishedFrames = outDir / "frames";
    if (video && !videoWritten) {
      std::cerr << "weft: --video: ffmpeg failed; the PNG frames are in " << publishedFrames.string() << "\n";
    } else if (video && talk) {
      std::printf("wrote %s\n", videoFile.string().c_str());
    }

    if (talk) {
      printStageShares(world->profile());
      std::printf("wrote %s\n", metricsFile.string().c_str());
      if (options.obj) std::printf("wrote %d frame(s) to %s\n", framesDone + 1, publishedFrames.string().c_str());
      if (png) {
        std::printf("wrote %d PNG image(s) of %dx%d to %s (%s)\n", pngFrames, width, height,
                    publishedFrames.string().c_str(), pngWriter->glRenderer().c_str());
      }
    }
  } catch (const std::exception& e) {
    progress.finish();
    std::cerr << "weft: " << e.what() << "\n";
    return kExitFailure;
  }

  if (!finite) {
    std::cerr << "weft: the simulation became non-finite after frame " << framesDone << " (t = " << world->time()
              << " s); metrics were written with \"finite\": false\n";
    return kExitNonFinite;
  }
  if (!health.healthy()) {
    std::cerr << "weft: metrics were written with \"healthy\": false (see \"health\" in "
              << (outDir / "metrics.json").string() << ")\n";
    return kExitNonFinite;
  }
  return kExitOk;
}

Command addRunCommand(CLI::App& app) {
  // --frames and --threads are optional in RunOptions; CLI11 2.1 fills plain ints, so they are
  // parsed here and handed over only when given.
  struct Parsed {
    RunOptions options;
    int frames = 0;
    int threads = 1;
    CLI::Option* framesOption = nullptr;
    CLI::Option* threadsOption = nullptr;
  };
  auto parsed = std::make_shared<Parsed>();
  RunOptions& options = parsed->options;
  CLI::App* cli = app.add_subcommand("run", "Simulate a scene headless; write metrics.json (and OBJ frames)");
  cli->add_option("scene", options.scene, "Scene file (JSON), e.g. presets/scenes/hanging-sheet.json")->required();
  parsed->framesOption =
      cli->add_option("--frames", parsed->frames, "Frames to simulate (same as --set output.frames=N)")
          ->check(integerIn(0, limits::kMaxFrames));
  cli->add_option("--out", options.out, "Output folder (default: out/<scene name>)");
  cli->add_flag("--obj", options.obj, "Also write frames/frame_NNNN.obj for every frame (frame 0 = start)");
  cli->add_flag("--png", options.png,
                "Also render frames/frame_NNNN.png headless (OpenGL through EGL; no display needed)");
  cli->add_option("--every", options.every, "With --png: render every N-th frame (default 1)")
      ->check(integerIn(1, limits::kMaxFrames));
  cli->add_option("--size", options.size, "With --png: image size WxH in pixels (default 960x720)");
  cli->add_flag("--video", options.video, "--png, then encode DIR/frames.mp4 with ffmpeg when it is installed");
  cli->add_option("--set", options.overrides, "Override a scene value, e.g. --set solver.dt=0.005 (repeatable)")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
  parsed->threadsOption =
      cli->add_option("--threads", parsed->threads, "Worker threads (same as --set solver.threads=N)")
          ->check(integerIn(1, limits::kMaxThreads));
  cli->add_flag("--quiet,-q", options.quiet, "Print nothing but errors");
  cli->add_flag("--keep-going", options.keepGoing,
                "When the health check fails (runaway strain or energy, unresolved contact, failing solves), "
                "warn and finish the run instead of stopping; still exits 3");
  return {cli, [parsed] {
            RunOptions given = parsed->options;
            if (parsed->framesOption->count() > 0) given.frames = parsed->frames;
            if (parsed->threadsOption->count() > 0) given.threads = parsed->threads;
            return runScene(given);
          }};
}

}  // namespace weft::app
