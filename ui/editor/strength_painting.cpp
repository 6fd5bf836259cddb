#include "editor/strength_painting.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <system_error>

#include "collision/closest_points.h"
#include "png_writer.h"
#include "sim/world.h"

namespace weft::editor {

namespace {

constexpr double kPixelMetres = 0.004;  // a new map's pixel: finer than any edge of a usable cloth
constexpr int kFewestPixels = 16, kMostPixels = 1024;

nlohmann::json stateOf(const std::vector<std::uint8_t>& grey) { return nlohmann::json::binary(grey); }

std::uint8_t toByte(double g) { return static_cast<std::uint8_t>(std::lround(std::clamp(g, 0.0, 1.0) * 255.0)); }

}  // namespace

double brushCoverage(double distance, double radius) {
  if (!(radius > 0.0) || !(distance < radius)) return 0.0;
  return 0.5 * (1.0 + std::cos(std::numbers::pi * distance / radius));
}

Vec2 materialPointOfHit(const World& world, const ClothHit& hit) {
  const ClothMesh& mesh = world.cloth(hit.cloth);
  const Triangle& t = mesh.tris[static_cast<std::size_t>(hit.triangle)];
  // The hit lies on the triangle; its closest point's weights are its barycentrics, and stay
  // finite on a collapsed triangle (collision/closest_points.h).
  const PointTriangleClosest closest = closestPointOnTriangle(hit.point, mesh.x[t.v[0]], mesh.x[t.v[1]], mesh.x[t.v[2]]);
  const double* w = closest.weights;
  return w[0] * t.rest[0] + w[1] * t.rest[1] + w[2] * t.rest[2];
}

TearStrengthMap newStrengthMap(const Vec2& lo, const Vec2& hi, const std::string& image) {
  TearStrengthMap map;
  map.image = image;
  map.black = 0.05;  // room to paint a perforation far weaker than the table
  map.white = 1.0;
  map.width = std::clamp(static_cast<int>(std::ceil((hi.x() - lo.x()) / kPixelMetres)), kFewestPixels, kMostPixels);
  map.height = std::clamp(static_cast<int>(std::ceil((hi.y() - lo.y()) / kPixelMetres)), kFewestPixels, kMostPixels);
  map.grey.assign(static_cast<std::size_t>(map.width) * map.height, 1.0f);
  prepareStrengthMap(map, lo, hi);
  return map;
}

std::filesystem::path paintedMapFile(const std::filesystem::path& sceneFile, const std::string& clothName,
                                     const std::string& namedImage) {
  const std::filesystem::path folder = sceneFile.parent_path();
  const std::filesystem::path named(namedImage);
  std::error_code ec;
  if (!namedImage.empty() && named.is_relative() && !named.has_parent_path() &&
      std::filesystem::is_regular_file(folder / named, ec)) {
    return folder / named;
  }
  return folder / (sceneFile.stem().string() + "." + clothName + ".strength.png");
}

nlohmann::json withStrengthMapImage(const nlohmann::json& scene, int cloth, const std::string& image, double black,
                                    double white) {
  nlohmann::json next = scene;
  nlohmann::json& spec = next.at("cloths").at(static_cast<std::size_t>(cloth));
  if (!spec.contains("tear_strength_map")) spec["tear_strength_map"] = {{"black", black}, {"white", white}};
  spec["tear_strength_map"]["image"] = image;
  return next;
}

StrengthPainting::StrengthPainting(TearStrengthMap start, std::shared_ptr<EditClock> clock)
    : map_(std::move(start)), history_(nullptr) {
  grey_.resize(map_.grey.size());
  for (std::size_t i = 0; i < grey_.size(); ++i) grey_[i] = toByte(map_.grey[i]);
  base_ = grey_;
  refresh();
  history_ = EditHistory(stateOf(grey_));
  if (clock) history_.shareClock(std::move(clock));
}

void StrengthPainting::beginStroke() {
  strokeStart_ = grey_;
  coverage_.assign(grey_.size(), 0.0f);
  stroking_ = true;
}

bool StrengthPainting::dab(const Vec2& centre, const StrengthBrush& brush) {
  if (!stroking_) beginStroke();
  const int w = map_.width, h = map_.height;
  const double dx = (map_.hi.x() - map_.lo.x()) / w, dy = (map_.hi.y() - map_.lo.y()) / h;
  const double span = map_.white - map_.black;
  const double target = std::clamp((brush.multiplier - map_.black) / span, 0.0, 1.0);
  // Pixel centres at lo.x + (i + 1/2) dx and hi.y - (j + 1/2) dy (strength_map.h: row 0 at the top).
  const int i0 = std::max(0, static_cast<int>(std::floor((centre.x() - brush.radius - map_.lo.x()) / dx))),
            i1 = std::min(w - 1, static_cast<int>(std::ceil((centre.x() + brush.radius - map_.lo.x()) / dx)));
  const int j0 = std::max(0, static_cast<int>(std::floor((map_.hi.y() - centre.y() - brush.radius) / dy))),
            j1 = std::min(h - 1, static_cast<int>(std::ceil((map_.hi.y() - centre.y() + brush.radius) / dy)));
  bool changed = false;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Vec2 p(map_.lo.x() + (i + 0.5) * dx, map_.hi.y() - (j + 0.5) * dy);
      const double c = brushCoverage((p - centre).norm(), brush.radius);
      const std::size_t k = static_cast<std::size_t>(j) * w + i;
      if (!(c > coverage_[k])) continue;
      coverage_[k] = static_cast<float>(c);
      const double from = strokeStart_[k] / 255.0;
      const double to = brush.erase ? base_[k] / 255.0 : target;
      const std::uint8_t next = toByte(from + (to - from) * c);
      if (next != grey_[k]) {
        grey_[k] = next;
        changed = true;
      }
    }
  }
  if (changed) refresh();
  return changed;
}

void StrengthPainting::endStroke(const std::string& label) {
  if (!stroking_) return;
  stroking_ = false;
  coverage_.clear();
  history_.commit(stateOf(grey_), label);  // no step when nothing changed (EditHistory)
}

void StrengthPainting::undo() {
  history_.undo();
  show(history_.current());
}

void StrengthPainting::redo() {
  history_.redo();
  show(history_.current());
}

void StrengthPainting::show(const nlohmann::json& state) {
  grey_ = state.get_binary();
  refresh();
}

void StrengthPainting::refresh() {
  for (std::size_t i = 0; i < grey_.size(); ++i) map_.grey[i] = static_cast<float>(grey_[i] / 255.0);  // as readStrengthImage
  prepareStrengthMap(map_, map_.lo, map_.hi);
  shared_.reset();
}

std::shared_ptr<const TearStrengthMap> StrengthPainting::sharedMap() const {
  if (!shared_) shared_ = std::make_shared<const TearStrengthMap>(map_);
  return shared_;
}

void StrengthPainting::savePng(const std::filesystem::path& file) {
  std::vector<std::uint8_t> rgba(grey_.size() * 4);
  for (std::size_t i = 0; i < grey_.size(); ++i) {
    rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = grey_[i];
    rgba[4 * i + 3] = 255;
  }
  ui::writePng(file, rgba, map_.width, map_.height);
  history_.markSaved();
}

}  // namespace weft::editor
