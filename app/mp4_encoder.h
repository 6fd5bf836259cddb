#pragma once
// An MP4 written by Debian's ffmpeg command-line tool, fed raw RGBA frames through a pipe as they
// are rendered, so no frame touches the disk. The file appears whole or not at all: ffmpeg writes
// FILE.partial and finish() renames it to FILE once ffmpeg has exited cleanly; an encoder
// destroyed before finish() (an error elsewhere) stops ffmpeg and removes the partial file.
//
// H.264 (libx264), yuv420p (what players expect; odd sizes are padded by one pixel), one encoder
// thread and ffmpeg's bitexact flags, so the same frames give the same bytes with the same ffmpeg.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace weft::app {

class Mp4Encoder {
 public:
  // Starts ffmpeg. Throws std::runtime_error when it cannot (ffmpeg missing: see ffmpegInstalled).
  Mp4Encoder(std::filesystem::path file, int width, int height, double fps);
  ~Mp4Encoder();
  Mp4Encoder(const Mp4Encoder&) = delete;
  Mp4Encoder& operator=(const Mp4Encoder&) = delete;

  // width * height * 4 bytes, RGBA8, rows top-down (OffscreenFramebuffer::readPixels). Throws
  // std::runtime_error when ffmpeg has stopped reading (its own message is on stderr).
  void addFrame(const std::vector<std::uint8_t>& rgba);
  // Waits for ffmpeg and moves the file into place. Throws std::runtime_error when ffmpeg failed.
  void finish();

  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_, partial_;
  int width_, height_;
  std::FILE* pipe_ = nullptr;
};

// True when the `ffmpeg` program is on PATH.
bool ffmpegInstalled();

}  // namespace weft::app
