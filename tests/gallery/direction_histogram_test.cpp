// The gallery's direction histogram: torn length in bins centred on 0, 22.5, ..., 157.5 degrees.
#include <gtest/gtest.h>

#include "gallery/direction_histogram.h"

namespace weft::gallery {
namespace {

TornSegment segment(double x0, double y0, double x1, double y1) { return TornSegment{Vec2(x0, y0), Vec2(x1, y1)}; }

TEST(DirectionHistogram, BinsTornLengthByLineDirectionCentredOnMultiplesOf22point5Degrees) {
  EXPECT_EQ(directionBinOf(0.0), 0);
  EXPECT_EQ(directionBinOf(11.0), 0);
  EXPECT_EQ(directionBinOf(11.5), 1);
  EXPECT_EQ(directionBinOf(170.0), 0) << "a line at 170 degrees is 10 degrees from horizontal";
  EXPECT_EQ(directionBinOf(90.0), 4);
  EXPECT_EQ(directionBinOf(135.0), 6);

  const std::vector<TornSegment> segments{segment(0, 0, 0.3, 0),       // horizontal, 0.3 m
                                          segment(0, 0, 0, 0.1),       // vertical, 0.1 m
                                          segment(0.1, 0.1, 0.2, 0.2),  // 45 degrees
                                          segment(0.2, 0.0, 0.1, 0.1)};  // 135 degrees
  const DirectionHistogram h = directionHistogram(segments);
  EXPECT_NEAR(h.length[0], 0.3, 1e-12);
  EXPECT_NEAR(h.length[4], 0.1, 1e-12);
  EXPECT_NEAR(h.length[2], std::sqrt(0.02), 1e-12);
  EXPECT_NEAR(h.length[6], std::sqrt(0.02), 1e-12);
  EXPECT_NEAR(h.total(), 0.4 + 2 * std::sqrt(0.02), 1e-12);
  EXPECT_EQ(h.largestBin(), 0);
  EXPECT_NEAR(h.share(0), 0.3 / h.total(), 1e-12);
  EXPECT_EQ(DirectionHistogram{}.share(3), 0.0);
}

}  // namespace
}  // namespace weft::gallery
