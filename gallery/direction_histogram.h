#pragma once
// Torn length by direction in material space, in eight bins of 22.5 degrees centred on 0, 22.5,
// ..., 157.5 (0 = the sheet's material x, 90 = its y; lines have no sense, so 170 degrees falls in
// the 0 bin). Centred bins keep a grid's horizontal, vertical and diagonal edges in the middle of
// a bin, where rounding cannot move them across a border.
#include <array>
#include <vector>

#include "gallery/tear_measures.h"

namespace weft::gallery {

inline constexpr int kDirectionBins = 8;
inline constexpr double kDirectionBinDeg = 180.0 / kDirectionBins;

struct DirectionHistogram {
  std::array<double, kDirectionBins> length{};  // m of torn length in each bin
  double total() const;
  double share(int bin) const;  // of the total; 0 when nothing tore
  int largestBin() const;
};

int directionBinOf(double directionDeg);  // [0, 180) -> bin index
DirectionHistogram directionHistogram(const std::vector<TornSegment>& segments);

}  // namespace weft::gallery
