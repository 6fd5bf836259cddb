#pragma once
// How long a run will take, said before it starts when it is long: a scene asking for minutes or
// hours of work should not look like a hang. The estimate counts vertex-substeps (cloth vertices x
// substeps x steps) at a cost measured on the presets of this project; it is a rough guide (contact
// and tearing vary a lot), refined after the first frame from the time that frame took.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace weft::app {

// Seconds per cloth vertex per substep at 32 x 32: the presets step in 0.7 ms (hanging sheet) to
// 2.9 ms (cloth on a ball, with contact) on the reference machine (README), 0.7-2.8 us a vertex.
inline constexpr double kSecondsPerVertexSubstep = 2e-6;
inline constexpr double kReferenceVertices = 1024.0;
// Runs expected to take longer than this are announced, even with --quiet.
inline constexpr double kLongRunSeconds = 60.0;

// The work per vertex grows with the mesh (more CG iterations, larger factorizations): the first
// frames of the hanging sheet took 6.7x, 6.8x and 8.7x longer for each 4x more vertices from
// 32 x 32 to 256 x 256, n^1.4 to n^1.6, so the cost is taken as growing with n^1.5.
inline double estimatedRunSeconds(std::int64_t vertices, std::int64_t substepsPerStep, std::int64_t steps) {
  const double n = static_cast<double>(vertices);
  const double growth = std::sqrt(std::max(1.0, n / kReferenceVertices));
  return kSecondsPerVertexSubstep * n * growth * static_cast<double>(substepsPerStep) * static_cast<double>(steps);
}

// "3.2 minutes", "2.5 hours", "41 days".
inline std::string describeDuration(double seconds) {
  char text[64];
  if (seconds < 120.0) std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 2.0 * 3600.0) std::snprintf(text, sizeof text, "%.1f minutes", seconds / 60.0);
  else if (seconds < 2.0 * 86400.0) std::snprintf(text, sizeof text, "%.1f hours", seconds / 3600.0);
  else std::snprintf(text, sizeof text, "%.3g days", seconds / 86400.0);
  return text;
}

}  // namespace weft::app
