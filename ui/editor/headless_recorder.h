#pragma once
// Playback's "record": the scene as edited so far is run headless by `weft run --png [--video]`
// (the same path as command-line capture, EGL and all) in a child process, so the live view keeps
// running while frames are written. The edited document is written beside the scene file (so its
// relative paths still resolve) for the child to read, and removed when the child is done.
#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

namespace weft::editor {

class HeadlessRecorder {
 public:
  explicit HeadlessRecorder(std::filesystem::path weftBinary) : weftBinary_(std::move(weftBinary)) {}
  ~HeadlessRecorder();  // waits for a recording in progress
  HeadlessRecorder(const HeadlessRecorder&) = delete;
  HeadlessRecorder& operator=(const HeadlessRecorder&) = delete;

  // Starts recording `frames` frames of `scene` (the document's JSON; `sceneFile` is where it
  // lives) into outDir/frames (and outDir/frames.mp4 with `video`). False when one is running.
  bool start(const nlohmann::json& scene, const std::filesystem::path& sceneFile, const std::filesystem::path& outDir,
             int frames, bool video);
  bool running() const { return running_; }
  // What the last finished recording said (where the frames are, or why it failed).
  std::string lastMessage() const;
  void wait();

 private:
  std::filesystem::path weftBinary_;
  std::thread worker_;
  std::atomic<bool> running_{false};
  mutable std::mutex mutex_;
  std::string message_;
};

}  // namespace weft::editor
