#include "gallery/scene_measure.h"

#include "contact/obstacle.h"

namespace weft::gallery {

SceneMeasure measureScene(const World& world, int ball) {
  SceneMeasure measure;
  measure.time = world.time();
  measure.tears = world.tearStats().tears;
  std::vector<TornSegment> segments;
  for (int c = 0; c < world.clothCount(); ++c) {
    const ClothMesh& mesh = world.cloth(c);
    const std::vector<TornSegment> torn = tornSegments(mesh);
    segments.insert(segments.end(), torn.begin(), torn.end());
    for (const Edge& e : mesh.edges) measure.cutEdges += e.cut ? 1 : 0;
  }
  measure.directions = directionHistogram(segments);
  measure.shareNearX = shareOfLengthWithin(segments, 0.0, 22.5);
  measure.shareNearY = shareOfLengthWithin(segments, 90.0, 22.5);
  measure.flap = flapMeasure(segments);
  if (ball >= 0 && ball < world.obstacleCount()) measure.ballEnd = world.obstacle(ball).body.state.position;
  return measure;
}

nlohmann::json sceneMeasureJson(const SceneMeasure& m) {
  nlohmann::json bins = nlohmann::json::array();
  for (int b = 0; b < kDirectionBins; ++b) {
    bins.push_back({{"direction_deg", b * kDirectionBinDeg}, {"torn_length_m", m.directions.length[b]},
                    {"share", m.directions.share(b)}});
  }
  nlohmann::json out = {{"time_s", m.time},
                        {"tears", m.tears},
                        {"cut_edges", m.cutEdges},
                        {"torn_length_m", m.directions.total()},
                        {"direction_histogram", bins},
                        {"share_within_22_5_deg_of_horizontal", m.shareNearX},
                        {"share_within_22_5_deg_of_vertical", m.shareNearY},
                        {"flap",
                         {{"vertical_m", m.flap.vertical},
                          {"left_group_m", m.flap.left},
                          {"right_group_m", m.flap.right},
                          {"separation_m", m.flap.separation},
                          {"joining_m", m.flap.joining}}}};
  if (m.ballEnd) out["ball_end_m"] = {m.ballEnd->x(), m.ballEnd->y(), m.ballEnd->z()};
  return out;
}

}  // namespace weft::gallery
