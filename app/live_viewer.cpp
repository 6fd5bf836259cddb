#include "live_viewer.h"

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include "command.h"
#include "glfw_window.h"
#include "orbit_controls.h"
#include "png_writer.h"
#include "render_view.h"
#include "scene_renderer.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

std::string titleOf(const ui::LiveSimulation& simulation) { return "Weft: " + simulation.status(); }

// The scene's camera, framing the world as it is now (its start), as headless runs do.
ui::OrbitCamera startCamera(const World& world, ui::PixelSize size) {
  const double aspect = size.height > 0 ? static_cast<double>(size.width) / size.height : 1.0;
  return ui::defaultCamera(ui::renderViewOf(world), world.scene().output.camera, aspect);
}

void reportStop(const ui::LiveSimulation& simulation) {
  std::cerr << "weft edit: the simulation became non-finite at t = " << simulation.world().time()
            << " s; stopped (R reloads the scene)\n";
}

// Space, N and R; returns false when the user asked to quit (Esc).
bool applyKeys(ui::LiveSimulation& simulation, const ui::WindowInput& input) {
  for (ui::Key key : input.keysPressed) {
    switch (key) {
      case ui::Key::kEscape:
        return false;
      case ui::Key::kSpace:
        simulation.togglePause();
        break;
      case ui::Key::kN:
        if (simulation.stepOnce()) reportStop(simulation);
        break;
      case ui::Key::kR:
        try {
          simulation.reload();
        } catch (const InputError& e) {
          std::cerr << "weft edit: cannot reload, keeping the current state: " << e.what() << "\n";
        }
        break;
    }
  }
  return true;
}

}  // namespace

int runLiveViewer(ui::LiveSimulation& simulation, const LiveViewerOptions& options) {
  ui::WindowSettings settings;
  settings.title = titleOf(simulation);
  ui::GlfwWindow window(settings);
  ui::SceneRenderer renderer;
  ui::OrbitCamera camera = startCamera(simulation.world(), window.framebufferSize());
  ui::OrbitControls controls;
  std::printf("weft edit: %s (%s)\n  Space pause/resume, N step when paused, R reload, Esc quit; "
              "left drag orbits, right or middle drag pans, the wheel zooms\n",
              simulation.scene().file.string().c_str(), window.glRenderer().c_str());
  std::fflush(stdout);

  auto draw = [&] {
    window.bindDefaultFramebuffer();
    const ui::PixelSize size = window.framebufferSize();
    if (size.width > 0 && size.height > 0) {  // zero while minimized
      renderer.draw(ui::renderViewOf(simulation.world()), camera, size.width, size.height);
    }
  };

  // The first displayed frame is the scene's start; each later one advances the simulation first.
  int displayed = 0;
  while (!window.shouldClose()) {
    window.pollEvents();
    if (!applyKeys(simulation, window.input())) break;
    controls.update(camera, window.input().mouse, window.windowSize().height);
    if (displayed > 0 && simulation.advanceFrame()) reportStop(simulation);
    window.setTitle(titleOf(simulation));
    draw();
    window.swapBuffers();
    ++displayed;
    if (options.frames && displayed >= *options.frames) break;
  }

  if (!options.screenshot.empty()) {
    // The back buffer's contents are undefined after a swap; nothing has changed since the last
    // displayed frame, so drawing again gives that frame, read before any swap.
    draw();
    const ui::PixelSize size = window.framebufferSize();
    try {
      ui::writePng(options.screenshot, window.readBackBuffer(), size.width, size.height);
      std::printf("wrote %s (%dx%d)\n", options.screenshot.string().c_str(), size.width, size.height);
    } catch (const std::exception& e) {
      std::cerr << "weft edit: --screenshot: cannot write " << options.screenshot.string() << ": " << e.what()
                << "\n";
      return kExitFailure;
    }
  }
  return simulation.stopped() ? kExitNonFinite : kExitOk;
}

}  // namespace weft::app
