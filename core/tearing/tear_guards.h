#pragma once
// Mesh-quality limits a tear respects: it follows an existing edge rather than make a bad triangle.

namespace weft {

struct TearGuards {
  // Never create an edge shorter than this (m, material space). 1 mm: far below the element size
  // of the presets (3 cm for a 1 m, 32 x 32 grid), so it only stops near-degenerate splits, and
  // a quarter of the default contact thickness (4 mm). Scale it with the mesh for finer cloth.
  double minEdgeLength = 1e-3;
  // Never create a triangle with an angle below this (degrees). A grid starts at 45; 15 keeps
  // the membrane's conditioning (which grows like 1 / sin of the smallest angle) within a factor
  // of three of the grid's, while letting a tear cross a triangle at up to 15 degrees from an edge.
  double minAngleDeg = 15.0;
  // A tear line this close in angle to an existing edge at the vertex follows that edge (degrees)
  // even where crossing would be allowed: fewer, better-shaped elements for a negligible change
  // of path. 5, as ARCSim snaps (arcsim-tearing-notes.md, "Splitting the mesh").
  double snapAngleDeg = 5.0;
};

}  // namespace weft
