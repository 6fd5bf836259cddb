#pragma once
// Scenes the tearing tests share: a sheet pulled outward along its four edges (a load that picks
// no direction in its middle), on a regular grid or an irregular mesh.
#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"
#include "support/test_scenes.h"
#include "tearing/tear_table.h"

namespace weft::test {

inline TearTable tearTable(std::vector<double> strength, double unit) {
  TearTable t;
  t.strength = std::move(strength);
  t.unitNPerM = unit;
  return t;
}

// The thesis' growth, the default before issue 17: one line per step from each triangle's own
// stress, a crack starting in the step its omega passes 1. Tests whose claim is about that mode
// (one step of the stage read on its own, lines per step) set it.
inline Scene inOnePassMode(Scene scene) {
  scene.tearing.propagate = false;
  scene.tearing.stressLength = 0.0;
  scene.tearing.incubation = 0.0;
  return scene;
}

inline PinGroup edgePins(Vec2 lo, Vec2 hi, const Vec3& pull, double seconds) {
  PinGroup group;
  group.restBox = std::pair(lo, hi);
  group.script = {{0.0, Vec3::Zero()}, {seconds, pull}};
  return group;
}

// A 1 m sheet (`resolution` vertices a side) held along its four edges (corners free), each edge pulled
// outward by `pull` metres over `seconds`: a (nearly) equal load in all directions in the middle
// of the sheet. No gravity.
inline Scene biaxialSheet(int resolution, const TearTable& tears, double weftDeg, bool dense, double pull = 0.12,
                          double seconds = 1.0) {
  const int cells = resolution - 1;
  Scene scene = hangingSheet(isotropicMaterial(2000.0, 0.3, 1e-5), resolution, 1.0 / 240);
  ClothSpec& cloth = scene.cloths[0];
  cloth.material.tearTable = tears;
  cloth.weftAngleDeg = weftDeg;
  const double e = 0.5 / cells;   // half a cell
  const double in = 1.5 / cells;  // keeps the corners free
  cloth.pins = {edgePins({-e, in}, {e, 1.0 - in}, {-pull, 0, 0}, seconds),
                edgePins({1.0 - e, in}, {1.0 + e, 1.0 - in}, {pull, 0, 0}, seconds),
                edgePins({in, -e}, {1.0 - in, e}, {0, -pull, 0}, seconds),
                edgePins({in, 1.0 - e}, {1.0 - in, 1.0 + e}, {0, pull, 0}, seconds)};
  scene.forces.gravity = Vec3::Zero();
  scene.forces.damping.mass = 0.5;
  scene.tearing.denseLines = dense;
  return scene;
}

// An OBJ of a 1 m sheet on an irregular mesh: a grid of `cells` cells whose interior points are
// moved at random by up to `jitter` cells, each cell split along a random diagonal. Rest shape
// (vt) and position (v) agree. Deterministic for a seed.
inline std::string irregularSheetObj(int cells, double jitter, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  std::bernoulli_distribution flip(0.5);
  std::ostringstream obj;
  obj.precision(17);
  const double h = 1.0 / cells;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      double x = i * h, y = j * h;
      if (i > 0 && i < cells) x += offset(random) * h;
      if (j > 0 && j < cells) y += offset(random) * h;
      obj << "v " << x << ' ' << y << " 0\nvt " << x << ' ' << y << '\n';
    }
  }
  auto id = [&](int i, int j) { return j * (cells + 1) + i + 1; };
  auto corner = [&](int k) { return std::to_string(k) + "/" + std::to_string(k); };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (flip(random)) {
        obj << "f " << corner(a) << ' ' << corner(b) << ' ' << corner(c) << '\n';
        obj << "f " << corner(a) << ' ' << corner(c) << ' ' << corner(d) << '\n';
      } else {
        obj << "f " << corner(a) << ' ' << corner(b) << ' ' << corner(d) << '\n';
        obj << "f " << corner(b) << ' ' << corner(c) << ' ' << corner(d) << '\n';
      }
    }
  }
  return obj.str();
}

// biaxialSheet's load on the irregular sheet written to `objFile`.
inline Scene biaxialIrregularSheet(const std::filesystem::path& objFile, int cells, const TearTable& tears,
                                   double weftDeg, bool dense) {
  Scene scene = biaxialSheet(cells + 1, tears, weftDeg, dense);
  ClothSpec& cloth = scene.cloths[0];
  cloth.grid.reset();
  ObjSpec obj;
  obj.path = objFile;
  cloth.obj = obj;
  return scene;
}

}  // namespace weft::test
