// Pins on an OBJ cloth name the file's `v` lines (issue 17, goal 7). An irregular sheet whose
// `v` lines are in an order no face follows, pinned by `v` line at its two top corners, holds
// exactly those corners and hangs at rest with the small strain of a sheet hanging from its
// corners; the same ids read in order of first use by a face (the old numbering) name two other
// points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "sim/world.h"
#include "support/temp_dir.h"

namespace weft {
namespace {

using nlohmann::json;

constexpr int kSide = 9;  // vertices per side of the 1 m sheet

// Where the sheet's vertex (ix, iy) is: interior vertices moved off the grid by up to a third of
// a cell, deterministically, so that no two triangles are alike.
Vec2 irregularPoint(int ix, int iy) {
  const double cell = 1.0 / (kSide - 1);
  const bool interior = ix > 0 && ix < kSide - 1 && iy > 0 && iy < kSide - 1;
  const double dx = interior ? 0.3 * cell * std::sin(12.9898 * ix + 78.233 * iy) : 0.0;
  const double dy = interior ? 0.3 * cell * std::cos(39.3468 * ix + 11.135 * iy) : 0.0;
  return Vec2(ix * cell + dx, iy * cell + dy);
}

struct IrregularSheet {
  std::string obj;
  std::vector<Vec2> pointOfVLine;  // [v line, from 0]
  std::vector<int> firstUseOrder;  // v lines in the order the faces first use them
};

// The grid point of grid vertex g is written on `v` line (g * 29) mod n: a shuffled but fixed
// order. Faces go row by row, alternating diagonals. UVs equal positions (metres).
IrregularSheet irregularSheet() {
  const int n = kSide * kSide;
  IrregularSheet sheet;
  sheet.pointOfVLine.resize(n);
  std::vector<int> lineOf(n);
  for (int g = 0; g < n; ++g) {
    lineOf[g] = (g * 29) % n;
    sheet.pointOfVLine[lineOf[g]] = irregularPoint(g % kSide, g / kSide);
  }
  for (const Vec2& p : sheet.pointOfVLine) sheet.obj += "v " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " 0\n";
  for (const Vec2& p : sheet.pointOfVLine) sheet.obj += "vt " + std::to_string(p.x()) + " " + std::to_string(p.y()) + "\n";
  auto corner = [&](int ix, int iy) {
    const int line = lineOf[iy * kSide + ix];
    if (std::find(sheet.firstUseOrder.begin(), sheet.firstUseOrder.end(), line) == sheet.firstUseOrder.end()) {
      sheet.firstUseOrder.push_back(line);
    }
    return " " + std::to_string(line + 1) + "/" + std::to_string(line + 1);
  };
  for (int iy = 0; iy + 1 < kSide; ++iy) {
    for (int ix = 0; ix + 1 < kSide; ++ix) {
      if ((ix + iy) % 2 == 0) {
        sheet.obj += "f" + corner(ix, iy) + corner(ix + 1, iy) + corner(ix + 1, iy + 1) + "\n";
        sheet.obj += "f" + corner(ix, iy) + corner(ix + 1, iy + 1) + corner(ix, iy + 1) + "\n";
      } else {
        sheet.obj += "f" + corner(ix, iy) + corner(ix + 1, iy) + corner(ix, iy + 1) + "\n";
        sheet.obj += "f" + corner(ix + 1, iy) + corner(ix + 1, iy + 1) + corner(ix, iy + 1) + "\n";
      }
    }
  }
  return sheet;
}

int vLineAt(const IrregularSheet& sheet, const Vec2& point) {
  for (std::size_t k = 0; k < sheet.pointOfVLine.size(); ++k) {
    if ((sheet.pointOfVLine[k] - point).norm() < 1e-9) return static_cast<int>(k);
  }
  ADD_FAILURE() << "no v line at " << point.transpose();
  return -1;
}

struct Hung {
  std::vector<Vec3> pinnedAtStart;
  double maxStrain = 0.0;
  double kineticEnergy = 0.0;
};

// Hangs the sheet for 3 s from the pin ids given and reports where the pins were and the strain.
Hung hang(const IrregularSheet& sheet, const std::vector<int>& pinIds) {
  test::TempDir dir;
  dir.write("irregular.obj", sheet.obj);
  const json scene = {
      {"name", "irregular-obj-sheet"},
      {"cloths", {{{"mesh", {{"obj", {{"path", "irregular.obj"}}}}}, {"material", "isotropic-cotton"},
                   {"pins", {{{"vertices", pinIds}}}}}}},
      {"forces", {{"damping", {{"mass", 1.0}}}}},
      {"stages", {{"collision", false}}},
  };
  World world(loadScene(dir.write("scene.json", scene.dump())));
  Hung hung;
  const ClothMesh& mesh = world.cloth(0);
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    if (mesh.pinned[v]) hung.pinnedAtStart.push_back(mesh.x[v]);
  }
  for (int step = 0; step < 180; ++step) world.step();
  hung.maxStrain = world.metrics().maxStrain;
  hung.kineticEnergy = world.metrics().kineticEnergy;
  return hung;
}

TEST(ObjClothPins, AnIrregularSheetPinnedByVLinesRestsWithSmallStrain) {
  const IrregularSheet sheet = irregularSheet();
  const int topLeft = vLineAt(sheet, Vec2(0, 1));
  const int topRight = vLineAt(sheet, Vec2(1, 1));
  // The faces do not use the v lines in file order, so the two numberings differ at the corners.
  ASSERT_NE(sheet.firstUseOrder[topLeft], topLeft);
  ASSERT_NE(sheet.firstUseOrder[topRight], topRight);

  const auto pinsTheTopCorners = [](const Hung& hung) {
    return hung.pinnedAtStart.size() == 2 &&
           std::count(hung.pinnedAtStart.begin(), hung.pinnedAtStart.end(), Vec3(0, 1, 0)) == 1 &&
           std::count(hung.pinnedAtStart.begin(), hung.pinnedAtStart.end(), Vec3(1, 1, 0)) == 1;
  };
  const Hung byVLine = hang(sheet, {topLeft, topRight});
  EXPECT_TRUE(pinsTheTopCorners(byVLine));
  // Hanging from two corners under its own weight: 0.6 % at rest (cotton, E h = 4000 N/m).
  EXPECT_LT(byVLine.maxStrain, 0.02);
  EXPECT_LT(byVLine.kineticEnergy, 1e-4);

  // The ids as the old numbering read them: the topLeft-th and topRight-th vertex the faces used,
  // somewhere else on the sheet.
  const Hung byFirstUse = hang(sheet, {sheet.firstUseOrder[topLeft], sheet.firstUseOrder[topRight]});
  EXPECT_FALSE(pinsTheTopCorners(byFirstUse));
}

}  // namespace
}  // namespace weft
