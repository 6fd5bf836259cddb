#include "staged_output.h"

#include <system_error>
#include <utility>

#include "frame_obj_writer.h"
#include "frame_png_writer.h"

namespace weft::app {

namespace fs = std::filesystem;

StagedOutput::StagedOutput(fs::path outDir) : outDir_(std::move(outDir)), staging_(outDir_ / ".weft-partial") {
  fs::create_directories(outDir_);
  fs::remove_all(staging_);  // what a killed run left
  fs::create_directories(staging_);
}

StagedOutput::~StagedOutput() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagedOutput::publish(bool obj, bool png) {
  fs::remove(outDir_ / "metrics.json");
  const fs::path framesDir = outDir_ / "frames";
  if (obj) removeOldFrames(framesDir);
  if (png) removeOldPngFrames(framesDir);
  fs::remove(outDir_ / "frames.mp4");

  const fs::path stagedFrames = staging_ / "frames";
  if (fs::is_directory(stagedFrames)) {
    fs::create_directories(framesDir);
    for (const auto& entry : fs::directory_iterator(stagedFrames)) {
      fs::rename(entry.path(), framesDir / entry.path().filename());
    }
  }
  if (fs::exists(staging_ / "frames.mp4")) fs::rename(staging_ / "frames.mp4", outDir_ / "frames.mp4");
  fs::rename(staging_ / "metrics.json", outDir_ / "metrics.json");
  fs::remove_all(staging_);
}

}  // namespace weft::app
