#pragma once
// The roofline of `weft bench`: how close the CG's matrix-vector product comes to the machine's
// memory bandwidth. The product streams ~8.4 bytes of matrix per two flops (3x3 blocks read from the
// column storage: a value and a ninth of a row index per nonzero), so its
// achieved bytes per second against a measured triad bandwidth (McCalpin's STREAM triad,
// a[i] = b[i] + s c[i]) says how much faster it could get at best.
#include <filesystem>
#include <vector>

#include "scene/scene.h"

namespace weft::app {

// Triad over three arrays of `doubles` doubles each (by default well beyond the caches: main
// memory), best of `repeats`; bytes counted as STREAM does (two reads, one write). GB/s = 1e9 B/s.
double measureTriadBandwidth(long doubles = 8L << 20, int repeats = 5);

struct ProductBandwidth {
  double megabytes = 0.0;  // streamed per product: values, indices, x and y (MB = 1e6 B)
  double ms = 0.0;         // per product, best of a few repeats
  double gigabytesPerSecond() const { return ms > 0.0 ? megabytes / ms : 0.0; }
};

// The product with the system matrix's pattern for the scene's first cloth (the CG's product on one
// thread, preconditioned_cg.cpp), with arbitrary values (the time depends on the pattern only).
ProductBandwidth measureProductBandwidth(const Scene& scene, const std::filesystem::path& sceneFile);

}  // namespace weft::app
