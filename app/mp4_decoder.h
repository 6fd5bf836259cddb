#pragma once
// Frames of a video decoded by the ffmpeg command-line tool, read as raw RGBA through a pipe, for
// `weft guess` to show a clip exactly as `weft study-videos` rendered it (no video library is
// linked: ffmpeg is already needed to make the clips).
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace weft::app {

class Mp4Decoder {
 public:
  // width x height: the size of the video's frames (the manifest's size rounded up to even, as
  // the encoder pads it). Throws std::runtime_error when ffmpeg cannot be started.
  Mp4Decoder(const std::filesystem::path& file, int width, int height);
  ~Mp4Decoder();
  Mp4Decoder(const Mp4Decoder&) = delete;
  Mp4Decoder& operator=(const Mp4Decoder&) = delete;

  // The next frame into `outRgba` (width * height * 4 bytes, rows top-down); false at the end.
  bool next(std::vector<std::uint8_t>& outRgba);

 private:
  std::FILE* pipe_ = nullptr;
  int width_, height_;
};

}  // namespace weft::app
