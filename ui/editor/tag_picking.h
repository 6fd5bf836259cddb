#pragma once
// Which feature of a tool a click would tag, found in screen space so that what the user sees
// under the cursor is what gets tagged (and highlighted before the click): a vertex when the
// cursor is right on it, else an edge when the cursor is on that edge's drawn segment (so a click
// along a blade's edge near a vertex tags the edge), else a vertex nearby. Features behind the
// tool's front surface at the cursor are not offered. No GL, no ImGui.
#include <array>
#include <optional>
#include <vector>

#include "orbit_camera.h"
#include "sim/world.h"

namespace weft::editor {

struct TagTarget {
  int vertex = -1;                  // a vertex id of the tool, or -1
  std::array<int, 2> edge{-1, -1};  // else an edge, its two vertex ids (a < b)
  bool isVertex() const { return vertex >= 0; }
};

struct TagPickSettings {
  double vertexPixels = 4.0;  // a vertex wins within this distance of the cursor
  double edgePixels = 7.0;    // then an edge whose segment passes this close, then a vertex as close
};

// The feature of obstacle `tool` under the cursor (x, y), pixels from the top-left of a
// width x height view seen through `camera`; none when nothing is close enough.
std::optional<TagTarget> pickTagTarget(const World& world, int tool, const ui::OrbitCamera& camera, double x, double y,
                                       int width, int height, const TagPickSettings& settings = {});

// Box select: the tool's edges whose two ends are drawn inside the screen rectangle between
// (x0, y0) and (x1, y1) (any corner order) and are not hidden behind the tool's own surface.
std::vector<std::array<int, 2>> edgesInBox(const World& world, int tool, const ui::OrbitCamera& camera, double x0, double y0,
                                           double x1, double y1, int width, int height);

}  // namespace weft::editor
