#pragma once
// `weft run --png`: frames rendered headless (EGL) into frames/frame_NNNN.png, and --video's
// frames.mp4 through ffmpeg when it is installed.
#include <filesystem>
#include <memory>
#include <string>

#include "sim/world.h"

namespace weft::app {

class FramePngWriter {
 public:
  // Starts EGL and compiles the shaders; the camera frames the world as it is now (its start).
  // Throws ui::GlContextError when EGL cannot start, std::runtime_error for other GL failures.
  FramePngWriter(const World& world, int width, int height);
  ~FramePngWriter();

  // Renders the world at its current time into frames/frame_NNNN.png (written atomically).
  void write(const World& world, const std::filesystem::path& framesDir, int frame);

  std::string glRenderer() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int width_, height_;
};

std::filesystem::path framePngPath(const std::filesystem::path& framesDir, int frame);

// Removes frame_*.png files left by an earlier run into the same folder.
void removeOldPngFrames(const std::filesystem::path& framesDir);

// Parses "WxH" (e.g. 1280x720); false when malformed or outside 16..8192.
bool parseImageSize(const std::string& text, int& outWidth, int& outHeight);

// True when `program` is an executable file in a folder of PATH.
bool onPath(const std::string& program);

// Encodes frames/frame_*.png into `video` with ffmpeg (H.264, yuv420p). Returns ffmpeg's status.
int encodeVideo(const std::filesystem::path& framesDir, const std::filesystem::path& video, double fps);

}  // namespace weft::app
