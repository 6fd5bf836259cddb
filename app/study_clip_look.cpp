#include "study_clip_look.h"

namespace weft::app {
namespace {

std::array<float, 3> sampleColour(study::Fabric fabric) {
  switch (fabric) {
    case study::Fabric::Denim:
      return {0.13f, 0.13f, 0.16f};  // black denim
    case study::Fabric::TShirt:
      return {0.55f, 0.56f, 0.58f};  // gray interlock
    case study::Fabric::Pants:
      return {0.16f, 0.27f, 0.68f};  // royal blue
    case study::Fabric::Swimsuit:
      return {0.93f, 0.93f, 0.91f};  // white
  }
  return {0.5f, 0.5f, 0.5f};
}

// Unlike all four samples: neither dark, grey, blue nor white.
constexpr std::array<float, 3> kNeutral{0.80f, 0.72f, 0.58f};

}  // namespace

void dressForStudy(ui::RenderView& view, study::Fabric fabric, bool textured) {
  for (ui::ClothView& cloth : view.cloths) {
    cloth.woven = textured;
    cloth.tint = textured ? sampleColour(fabric) : kNeutral;
    cloth.pattern = WeavePattern::Plain;
    cloth.threadPitch = 0.004;
  }
}

}  // namespace weft::app
