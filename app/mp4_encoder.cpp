#include "mp4_encoder.h"

#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <sys/wait.h>

#include "frame_png_writer.h"
#include "shell_quoted.h"

namespace weft::app {

bool ffmpegInstalled() { return onPath("ffmpeg"); }

Mp4Encoder::Mp4Encoder(std::filesystem::path file, int width, int height, double fps)
    : file_(std::move(file)), partial_(file_.string() + ".partial"), width_(width), height_(height) {
  // A write into the pipe of an ffmpeg that has exited raises SIGPIPE, whose default action ends
  // weft without a word; ignored, the write fails with EPIPE and addFrame says what happened.
  std::signal(SIGPIPE, SIG_IGN);
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.17g", fps);
  const std::string command = "ffmpeg -hide_banner -nostdin -loglevel error -y -f rawvideo -pix_fmt rgba -s " +
                              std::to_string(width) + "x" + std::to_string(height) + " -framerate " + rate +
                              " -i - -an -c:v libx264 -preset medium -crf 18 -pix_fmt yuv420p -threads 1"
                              " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -fflags +bitexact -flags:v +bitexact"
                              " -map_metadata -1 -movflags +faststart -f mp4 " +
                              shellQuoted(partial_.string());
  pipe_ = ::popen(command.c_str(), "w");
  if (pipe_ == nullptr) throw std::runtime_error("cannot start ffmpeg for " + file_.string());
}

Mp4Encoder::~Mp4Encoder() {
  if (pipe_ == nullptr) return;
  ::pclose(pipe_);  // ffmpeg sees the end of its input, finishes and exits; its file is unwanted
  std::error_code ignored;
  std::filesystem::remove(partial_, ignored);
}

void Mp4Encoder::addFrame(const std::vector<std::uint8_t>& rgba) {
  if (pipe_ == nullptr) throw std::logic_error("Mp4Encoder::addFrame after finish");
  const std::size_t bytes = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4;
  if (rgba.size() != bytes) throw std::logic_error("Mp4Encoder::addFrame: frame of the wrong size");
  if (std::fwrite(rgba.data(), 1, bytes, pipe_) != bytes)
    throw std::runtime_error("ffmpeg stopped reading frames for " + file_.string() + " (its message is above)");
}

void Mp4Encoder::finish() {
  if (pipe_ == nullptr) return;
  const int status = ::pclose(pipe_);
  pipe_ = nullptr;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::error_code ignored;
    std::filesystem::remove(partial_, ignored);
    throw std::runtime_error("ffmpeg failed to encode " + file_.string() +
                             (WIFEXITED(status) ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")" : ""));
  }
  std::filesystem::rename(partial_, file_);
}

}  // namespace weft::app
