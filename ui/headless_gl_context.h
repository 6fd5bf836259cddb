#pragma once
// An OpenGL 3.3 core context with no window and no X server: EGL on Mesa's surfaceless platform
// (llvmpipe on a machine without a GPU). Rendering goes into an OffscreenFramebuffer.
#include <stdexcept>
#include <string>

namespace weft::ui {

// EGL or the context could not start (no Mesa EGL, no usable driver, GL < 3.3).
struct GlContextError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class HeadlessGlContext {
 public:
  // Opens the surfaceless display, creates a 3.3 core context and makes it current on this
  // thread. Throws GlContextError with what failed.
  HeadlessGlContext();
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  std::string glRenderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string glVersion() const;   // GL_VERSION

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace weft::ui
