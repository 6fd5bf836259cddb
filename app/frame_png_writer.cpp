#include "frame_png_writer.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "frame_files.h"
#include "headless_gl_context.h"
#include "offscreen_framebuffer.h"
#include "png_writer.h"
#include "scene_renderer.h"

namespace weft::app {

struct FramePngWriter::Impl {
  ui::HeadlessGlContext context;
  ui::OffscreenFramebuffer framebuffer;
  ui::SceneRenderer renderer;
  ui::OrbitCamera camera;

  Impl(int width, int height) : framebuffer(width, height, 4) {}
};

FramePngWriter::FramePngWriter(const World& world, int width, int height)
    : impl_(std::make_unique<Impl>(width, height)), width_(width), height_(height) {
  impl_->camera = ui::defaultCamera(ui::renderViewOf(world), world.scene().output.camera,
                                    static_cast<double>(width) / height);
}

FramePngWriter::~FramePngWriter() = default;

void FramePngWriter::write(const World& world, const std::filesystem::path& framesDir, int frame) {
  impl_->framebuffer.bind();
  impl_->renderer.draw(ui::renderViewOf(world), impl_->camera, width_, height_);
  ui::writePng(framePngPath(framesDir, frame), impl_->framebuffer.readPixels(), width_, height_);
}

std::string FramePngWriter::glRenderer() const { return impl_->context.glRenderer(); }

std::filesystem::path framePngPath(const std::filesystem::path& framesDir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", frame);
  return framesDir / name;
}

void removeOldPngFrames(const std::filesystem::path& framesDir) { removeFrameFiles(framesDir, ".png", {"frame_"}); }

bool parseImageSize(const std::string& text, int& outWidth, int& outHeight) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra)) return false;
  if (w < 16 || h < 16 || w > 8192 || h > 8192) return false;
  outWidth = w;
  outHeight = h;
  return true;
}

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream folders(path);
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(folder) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

namespace {
std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

int encodeVideo(const std::filesystem::path& framesDir, const std::filesystem::path& video, double fps) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  const std::string command = "ffmpeg -y -loglevel error -framerate " + std::string(rate) +
                              " -pattern_type glob -i " + shellQuote((framesDir / "frame_*.png").string()) +
                              " -c:v libx264 -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' " +
                              shellQuote(video.string());
  return std::system(command.c_str());
}

}  // namespace weft::app
