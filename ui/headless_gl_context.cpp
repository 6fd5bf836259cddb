#include "headless_gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <cstdio>

namespace weft::ui {
namespace {

std::string eglErrorText(const char* what) {
  char text[160];
  std::snprintf(text, sizeof text, "EGL: %s failed (error 0x%04x)", what, static_cast<unsigned>(eglGetError()));
  return text;
}

}  // namespace

HeadlessGlContext::HeadlessGlContext() {
  // eglGetPlatformDisplay is EGL 1.5 (glvnd on Debian 12 has it); plain eglGetDisplay would need
  // EGL_PLATFORM=surfaceless in the environment.
  EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) throw GlContextError(eglErrorText("eglGetPlatformDisplay(surfaceless)"));
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) throw GlContextError(eglErrorText("eglInitialize"));
  display_ = display;

  auto fail = [this](const std::string& message) {
    eglTerminate(static_cast<EGLDisplay>(display_));
    display_ = nullptr;
    throw GlContextError(message);
  };
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) fail(eglErrorText("eglBindAPI(OpenGL)"));

  // Without EGL_PBUFFER_BIT Mesa's surfaceless platform offers no config at all.
  const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                     EGL_RED_SIZE,     8,               EGL_GREEN_SIZE,      8,
                                     EGL_BLUE_SIZE,    8,               EGL_ALPHA_SIZE,      8,
                                     EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  if (eglChooseConfig(display, configAttributes, &config, 1, &configCount) != EGL_TRUE || configCount < 1) {
    fail(eglErrorText("eglChooseConfig (no RGBA8 pbuffer-capable OpenGL config)"));
  }

  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT) fail(eglErrorText("eglCreateContext (OpenGL 3.3 core)"));
  context_ = context;
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    eglDestroyContext(display, context);
    context_ = nullptr;
    fail(eglErrorText("eglMakeCurrent (surfaceless)"));
  }
}

HeadlessGlContext::~HeadlessGlContext() {
  if (display_ == nullptr) return;
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != nullptr) eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
}

std::string HeadlessGlContext::glRenderer() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return text != nullptr ? text : "unknown";
}

std::string HeadlessGlContext::glVersion() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return text != nullptr ? text : "unknown";
}

}  // namespace weft::ui
