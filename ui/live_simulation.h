#pragma once
// A scene simulated while it is watched: the World plus the viewer's rules for advancing it.
// Running, it advances one output frame (stepsPerFrame steps) per displayed frame; paused, it
// advances one solver step at a time on request; a non-finite state stops it until the scene is
// reloaded. No GL and no window, so the editor can put its panels around the same object and
// tests can drive it directly.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "sim/world.h"

namespace weft::ui {

class LiveSimulation {
 public:
  // Loads the scene file with the overrides applied (scene/scene_json.h) and builds the world.
  // Throws InputError, naming the file and field, when the scene is bad.
  LiveSimulation(std::filesystem::path sceneFile, std::vector<std::string> overrides);

  const World& world() const { return *world_; }
  const Scene& scene() const { return world_->scene(); }

  bool paused() const { return paused_; }
  void togglePause() { paused_ = !paused_; }
  // The state became non-finite; nothing advances until reload().
  bool stopped() const { return stopped_; }

  // One displayed frame's worth: stepsPerFrame(scene) steps, unless paused or stopped.
  // Returns true when this call stopped the simulation (the state became non-finite).
  bool advanceFrame();
  // One solver step while paused (does nothing while running or stopped). Same return value.
  bool stepOnce();

  // Loads the scene file again (picking up edits to it) and starts over, keeping paused as it
  // is. Throws InputError and keeps the current world when the file is now bad.
  void reload();

  // For the window title: "hanging-sheet  t = 1.250 s  paused".
  std::string status() const;

 private:
  bool step(int steps);

  std::filesystem::path sceneFile_;
  std::vector<std::string> overrides_;
  std::unique_ptr<World> world_;
  bool paused_ = false;
  bool stopped_ = false;
};

}  // namespace weft::ui
