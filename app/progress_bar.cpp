#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace weft::app {

ProgressBar::ProgressBar(int total, std::string unit, bool enabled)
    : total_(std::max(total, 0)), unit_(std::move(unit)), enabled_(enabled),
      start_(std::chrono::steady_clock::now()), lastDraw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

bool ProgressBar::stderrIsTerminal() { return isatty(STDERR_FILENO) == 1; }

void ProgressBar::update(int done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  // Redrawing on every frame would slow down small scenes more than it helps.
  if (drawn_ && done < total_ && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  draw(done);
}

void ProgressBar::draw(int done) {
  constexpr int kWidth = 30;
  const double fraction = total_ > 0 ? std::clamp(double(done) / total_, 0.0, 1.0) : 1.0;
  const int filled = static_cast<int>(fraction * kWidth);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, ' ');
  std::fprintf(stderr, "\r[%s] %d/%d %s  %.1f s", bar.c_str(), done, total_, unit_.c_str(), seconds);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\n");
  drawn_ = false;
  enabled_ = false;
}

}  // namespace weft::app
