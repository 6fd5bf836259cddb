#pragma once
// Painting a cloth's tear strength map (tearing/strength_map.h) with a brush, undoably: the model
// behind the editor's "Tear strength" brush, without GL or ImGui so tests drive it.
//
// The map is painted in its own grey levels, kept as 8 bits a pixel: what the PNG saved beside
// the scene holds, so saving and loading again gives the painted multipliers exactly. One stroke
// (press to release) is one undo step of an EditHistory (snapshots of the grey levels) on the
// editor's shared EditClock, so Ctrl+Z takes it back in turn with the scene's other edits.
//
// Within a stroke the brush does not build up: each pixel moves from its grey before the stroke
// towards the brush's grey by the largest coverage any dab of the stroke gave it (as a stroke's
// opacity works in painting programs), so going over the same place in one drag does not darken
// it further and the 8-bit rounding cannot stall a slow drag. Erasing moves towards the map as
// it was when painting began (the file's grey levels, white for a new map): a perforation loaded
// from the scene survives erasing a brush mistake next to it.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/edit_history.h"
#include "sim/pick.h"
#include "tearing/strength_map.h"
#include "util/types.h"

namespace weft {
class World;
}

namespace weft::editor {

struct StrengthBrush {
  double radius = 0.03;      // m of material: where the coverage falls to 0
  double multiplier = 0.15;  // the multiplier painted at full coverage (clamped to [black, white])
  bool erase = false;        // towards the map as painting began instead of `multiplier`
};

// The brush's coverage at `distance` from its centre: a raised cosine (Hann window),
// 0.5 (1 + cos(pi d / R)) for d < R, else 0: 1 at the centre, falling smoothly to 0 at the rim.
double brushCoverage(double distance, double radius);

// The material point (m) a ray hit on a cloth lands on: the hit triangle's rest corners weighted
// by the hit point's barycentric coordinates in its current (deformed) triangle.
Vec2 materialPointOfHit(const World& world, const ClothHit& hit);

// The map a cloth gets on its first stroke when it has none: white over [lo, hi] (its material
// bounds) at about 4 mm a pixel (16 to 1024 pixels a side), black 0.05, white 1, named `image`.
TearStrengthMap newStrengthMap(const Vec2& lo, const Vec2& hi, const std::string& image);

// Where a cloth's painted map is saved: the image the cloth already names when that file lives
// beside the scene (a bare file name found in the scene's folder), else a new file there,
// "<scene stem>.<cloth name>.strength.png" (a shipped map in assets/ is never written over).
std::filesystem::path paintedMapFile(const std::filesystem::path& sceneFile, const std::string& clothName,
                                     const std::string& namedImage);

// The scene's cloth `cloth` reading its tear strength map from `image` (relative to the scene's
// folder); a cloth that had no map also gets the painted map's `black` and `white`.
nlohmann::json withStrengthMapImage(const nlohmann::json& scene, int cloth, const std::string& image, double black,
                                    double white);

class StrengthPainting {
 public:
  // Starts on `start` (a map as loaded, or newStrengthMap's), its grey levels rounded to 8 bits.
  StrengthPainting(TearStrengthMap start, std::shared_ptr<EditClock> clock);

  // The map as painted so far, prepared for sampling (strengthMultiplierAt works on it).
  const TearStrengthMap& map() const { return map_; }
  // The same, shared: one copy per change of the map, not per call (the viewport's tint reads it
  // every frame, and uploads it again only when the copy is a new one).
  std::shared_ptr<const TearStrengthMap> sharedMap() const;
  const std::vector<std::uint8_t>& grey() const { return grey_; }

  void beginStroke();
  // Paints one dab at material point `centre`; returns whether any pixel changed.
  bool dab(const Vec2& centre, const StrengthBrush& brush);
  // Commits the stroke as one undo step (nothing when it changed nothing).
  void endStroke(const std::string& label = "paint tear strength");
  bool stroking() const { return stroking_; }

  EditHistory& history() { return history_; }
  const EditHistory& history() const { return history_; }
  void undo();
  void redo();
  bool dirty() const { return history_.dirty(); }

  // Writes the grey levels as an 8-bit PNG (grey in R, G and B; stb_image reads it back as the
  // same luminance) through a temporary file and a rename, and marks them saved.
  void savePng(const std::filesystem::path& file);

 private:
  void show(const nlohmann::json& state);  // history state -> grey_ and map_
  void refresh();                          // grey_ -> map_'s grey and multipliers

  TearStrengthMap map_;
  mutable std::shared_ptr<const TearStrengthMap> shared_;  // sharedMap's copy of map_ (none: stale)
  std::vector<std::uint8_t> grey_;
  std::vector<std::uint8_t> base_;         // erasing goes back to these
  std::vector<std::uint8_t> strokeStart_;  // the grey levels when the stroke began
  std::vector<float> coverage_;            // the stroke's largest coverage per pixel
  bool stroking_ = false;
  EditHistory history_;
};

}  // namespace weft::editor
