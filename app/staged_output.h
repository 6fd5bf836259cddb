#pragma once
// A run's output appears all at once. Frames and metrics.json are written into a staging folder
// inside the output folder (OUT/.weft-partial, on the same file system, so moving is a rename),
// and only a run that got as far as writing its metrics moves them into OUT. A run that fails
// or is killed halfway leaves the previous run's files as they were, never new frames next to an
// old metrics.json; the next run clears what a killed one left in the staging folder.
#include <filesystem>

namespace weft::app {

class StagedOutput {
 public:
  // Creates OUT and an empty OUT/.weft-partial. Throws std::filesystem::filesystem_error.
  explicit StagedOutput(std::filesystem::path outDir);
  ~StagedOutput();  // removes the staging folder (after publish() it is already gone)
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  const std::filesystem::path& staging() const { return staging_; }

  // Moves the staged files into OUT: first the old metrics.json goes, then the old frames of the
  // kinds written this time (frame_*.obj and obstacle_*.obj with obj, frame_*.png with png, and
  // frames.mp4), then the new frames come in, and the new metrics.json last. Throws
  // std::filesystem::filesystem_error.
  void publish(bool obj, bool png);

 private:
  std::filesystem::path outDir_;
  std::filesystem::path staging_;
};

}  // namespace weft::app
