#pragma once
// A one-line progress bar on stderr, for long runs at a terminal. When disabled (stderr is a
// file or a pipe, or --quiet) it prints nothing, so logs and tests stay clean.
#include <chrono>
#include <string>

namespace weft::app {

class ProgressBar {
 public:
  ProgressBar(int total, std::string unit, bool enabled);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(int done);  // redraws at most a few times per second
  void finish();          // ends the line; called by the destructor if needed

  // True when stderr is an interactive terminal.
  static bool stderrIsTerminal();

 private:
  void draw(int done);

  int total_;
  std::string unit_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastDraw_;
};

}  // namespace weft::app
