#pragma once
// The tests' names for the torn-length measures, which live in gallery/tear_measures.h so that
// `weft gallery` prints the very numbers the tests assert.
#include "gallery/tear_measures.h"

namespace weft::test {

using gallery::Crack;
using gallery::cracks;
using gallery::flapMeasure;
using gallery::FlapMeasure;
using gallery::lineAngleBetweenDeg;
using gallery::segmentsInside;
using gallery::shareOfLengthWithin;
using gallery::tornLength;
using gallery::TornSegment;
using gallery::tornSegments;

}  // namespace weft::test
