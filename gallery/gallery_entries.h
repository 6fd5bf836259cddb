#pragma once
// The experiments of the thesis' Chapter 4 (Karaoz 2015, §4.1-§4.4), one entry per figure: the
// scene that reproduces it, how long to run it, the moments its contact sheet shows, and the claim
// its figure makes, which `judge` checks against what the run measured. Figures that need cutting
// (not built yet) are listed without a scene, so the gallery says what is missing.
#include <string>
#include <vector>

#include "gallery/scene_measure.h"

namespace weft::gallery {

// What a figure shows, as something a run can be checked for.
enum class ThesisClaim {
  TearsEveryWay,        // Figure 4.3: the isotropic cloth tears in every direction
  TearsAcross,          // Figure 4.4: horizontal tears only
  TwoVerticalsJoined,   // Figure 4.5: two vertical tears, then a horizontal one joining them
  ManyVertical,         // Figure 4.6: many vertical tears
  TearsUnderBluntTool,  // Figure 4.2: the hammer stretches the cloth until it tears
  BallStaysUp,          // Figure 4.9: the light ball stays on the ceiling
  BallFallsThrough,     // Figure 4.10: the heavy ball tears a horizontal line and drops
  NeedsCutting,         // Figures 4.1, 4.7, 4.8: cutting is not built yet
};

struct GalleryEntry {
  std::string id;          // names its files: ID.mp4, ID.png (contact sheet), ID-figure.png
  std::string section;     // "4.2"
  std::string figure;      // "Figure 4.4"
  std::string title;       // the figure's caption
  std::string thesisSays;  // what the thesis' text says the figure shows
  std::string scene;       // presets/scenes/NAME.json stem; empty when Weft cannot run it yet
  std::vector<std::string> sets;  // --set style overrides (e.g. one ball moved aside)
  double seconds = 0.75;          // s simulated
  std::vector<double> sheetTimes;  // s: the contact sheet's moments, the figure's own last
  double figureTime = 0.0;         // s: the moment ID-figure.png shows at full size
  double playbackSpeed = 1.0;      // the MP4 plays at this fraction of real time
  int ball = -1;                   // obstacle whose end position is reported (-1: none)
  char ballAxis = 'y';             // the coordinate that tells where it ended ('y' or 'z')
  ThesisClaim claim = ThesisClaim::NeedsCutting;
};

// In the thesis' order.
std::vector<GalleryEntry> galleryEntries();

struct Verdict {
  bool reproduced = false;
  std::string decidingNumber;  // the measured number the verdict rests on, and its threshold
};

// Not meaningful for NeedsCutting (never reproduced).
Verdict judge(const GalleryEntry& entry, const SceneMeasure& measure);

}  // namespace weft::gallery
