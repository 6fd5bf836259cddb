#include "gallery/direction_histogram.h"

#include <cmath>

namespace weft::gallery {

double DirectionHistogram::total() const {
  double sum = 0.0;
  for (double l : length) sum += l;
  return sum;
}

double DirectionHistogram::share(int bin) const {
  const double sum = total();
  return sum > 0.0 ? length[bin] / sum : 0.0;
}

int DirectionHistogram::largestBin() const {
  int best = 0;
  for (int b = 1; b < kDirectionBins; ++b) {
    if (length[b] > length[best]) best = b;
  }
  return best;
}

int directionBinOf(double directionDeg) {
  const int bin = static_cast<int>(std::floor((directionDeg + 0.5 * kDirectionBinDeg) / kDirectionBinDeg));
  return ((bin % kDirectionBins) + kDirectionBins) % kDirectionBins;
}

DirectionHistogram directionHistogram(const std::vector<TornSegment>& segments) {
  DirectionHistogram histogram;
  for (const TornSegment& s : segments) histogram.length[directionBinOf(s.directionDeg())] += s.length();
  return histogram;
}

}  // namespace weft::gallery
