#pragma once
// A framebuffer object to render into without a window: RGBA8 colour and 24-bit depth, optionally
// multisampled (resolved into a single-sample buffer before reading). Needs a current GL context.
#include <cstdint>
#include <vector>

namespace weft::ui {

class OffscreenFramebuffer {
 public:
  // samples: 1 for none, 4 for 4x MSAA. Throws std::runtime_error when the FBO is incomplete.
  OffscreenFramebuffer(int width, int height, int samples = 4);
  ~OffscreenFramebuffer();
  OffscreenFramebuffer(const OffscreenFramebuffer&) = delete;
  OffscreenFramebuffer& operator=(const OffscreenFramebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  void bind() const;  // as the draw target, with the viewport set to its size

  // Resolves the samples and returns width*height*4 bytes, RGBA8, rows top-down.
  std::vector<std::uint8_t> readPixels() const;

 private:
  int width_, height_, samples_;
  unsigned drawFbo_ = 0, colour_ = 0, depth_ = 0;  // multisampled when samples_ > 1
  unsigned resolveFbo_ = 0, resolveColour_ = 0;     // single-sample copy (samples_ > 1 only)
};

}  // namespace weft::ui
