#pragma once
// A band painted with the editor's brush across a cloth at y = 0.3 (material space), and the check
// that a sheet pulled equally in all directions then tears inside it: the brush's model and its
// hand-over to a running world are tested on the same band.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "editor/strength_painting.h"
#include "mesh/material_bounds.h"
#include "tearing/tear_record.h"

namespace weft::test {

inline constexpr double kPaintedBandY = 0.3;

// A stroke the whole width of `bounds`, radius 5 cm (coverage over 0.5 within 2.5 cm of it), down
// to 0.12 of the strength.
inline TearStrengthMap paintedBand(const MaterialBounds& bounds) {
  editor::StrengthPainting painting(editor::newStrengthMap(bounds.lo, bounds.hi, "band.png"), nullptr);
  editor::StrengthBrush brush;
  brush.radius = 0.05;
  brush.multiplier = 0.12;
  painting.beginStroke();
  for (double x = bounds.lo.x(); x <= bounds.hi.x() + 1e-9; x += 0.01) painting.dab(Vec2(x, kPaintedBandY), brush);
  painting.endStroke();
  return painting.map();
}

// The first tear, and 90% of them, within 2.5 cm and an edge of the band.
inline void expectTearsInsideBand(const std::vector<TearRecord>& log, double edge) {
  ASSERT_FALSE(log.empty());
  const Vec2 first = log.front().restPosition;
  EXPECT_LT(std::abs(first.y() - kPaintedBandY), 0.025 + edge) << "first tear at y = " << first.y();
  int inside = 0;
  for (const TearRecord& r : log) inside += std::abs(r.restPosition.y() - kPaintedBandY) < 0.025 + edge;
  EXPECT_GE(static_cast<double>(inside) / log.size(), 0.9);
}

}  // namespace weft::test
