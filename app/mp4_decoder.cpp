#include "mp4_decoder.h"

#include <stdexcept>
#include <string>

#include "shell_quoted.h"

namespace weft::app {

Mp4Decoder::Mp4Decoder(const std::filesystem::path& file, int width, int height) : width_(width), height_(height) {
  const std::string command = "ffmpeg -hide_banner -nostdin -loglevel error -i " + shellQuoted(file.string()) +
                              " -f rawvideo -pix_fmt rgba -";
  pipe_ = ::popen(command.c_str(), "r");
  if (pipe_ == nullptr) throw std::runtime_error("cannot start ffmpeg to play " + file.string());
}

Mp4Decoder::~Mp4Decoder() {
  if (pipe_ != nullptr) ::pclose(pipe_);
}

bool Mp4Decoder::next(std::vector<std::uint8_t>& outRgba) {
  const std::size_t bytes = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4;
  outRgba.resize(bytes);
  return std::fread(outRgba.data(), 1, bytes, pipe_) == bytes;
}

}  // namespace weft::app
