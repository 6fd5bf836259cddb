#include "offscreen_framebuffer.h"

#include <GL/glcorearb.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace weft::ui {
namespace {

void checkComplete(const char* which) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error(std::string("OpenGL: the ") + which + " framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
  }
}

}  // namespace

OffscreenFramebuffer::OffscreenFramebuffer(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples < 1 ? 1 : samples) {
  if (width <= 0 || height <= 0) throw std::runtime_error("OpenGL: framebuffer size must be positive");
  glGenFramebuffers(1, &drawFbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, drawFbo_);
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_DEPTH_COMPONENT24, width,
                                   height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  checkComplete("draw");

  if (samples_ > 1) {
    glGenFramebuffers(1, &resolveFbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_);
    glGenRenderbuffers(1, &resolveColour_);
    glBindRenderbuffer(GL_RENDERBUFFER, resolveColour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolveColour_);
    checkComplete("resolve");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

OffscreenFramebuffer::~OffscreenFramebuffer() {
  const GLuint renderbuffers[] = {colour_, depth_, resolveColour_};
  glDeleteRenderbuffers(3, renderbuffers);
  const GLuint framebuffers[] = {drawFbo_, resolveFbo_};
  glDeleteFramebuffers(2, framebuffers);
}

void OffscreenFramebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, drawFbo_);
  glViewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> OffscreenFramebuffer::readPixels() const {
  GLuint source = drawFbo_;
  if (samples_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, drawFbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    source = resolveFbo_;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  std::vector<std::uint8_t> bottomUp(row * static_cast<std::size_t>(height_));
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // GL's rows start at the bottom; images start at the top.
  std::vector<std::uint8_t> topDown(bottomUp.size());
  for (int y = 0; y < height_; ++y) {
    std::memcpy(topDown.data() + static_cast<std::size_t>(y) * row,
                bottomUp.data() + static_cast<std::size_t>(height_ - 1 - y) * row, row);
  }
  return topDown;
}

}  // namespace weft::ui
