#pragma once
// Where a cloth tore, measured in material space: how much of the torn length follows a direction,
// and the cracks as whole lines (the "direction" goal is stated in these terms). Shared by
// the tearing tests and `weft gallery`, which print the same numbers.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "tearing/vertex_fan.h"
#include "util/types.h"

namespace weft::gallery {

// Axial difference of two line directions (degrees, lines have no sense): in [0, 90].
inline double lineAngleBetweenDeg(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180.0 - d);
}

// One torn edge, counted once (both lips of a crack carry the same material segment).
struct TornSegment {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();  // material space (m)
  double length() const { return (b - a).norm(); }
  double directionDeg() const {
    double deg = std::atan2(b.y() - a.y(), b.x() - a.x()) * 180.0 / kPi;
    return deg < 0.0 ? deg + 180.0 : deg;
  }
};

inline std::vector<TornSegment> tornSegments(const ClothMesh& mesh) {
  std::vector<TornSegment> segments;
  for (const Edge& e : mesh.edges) {
    if (!(e.torn || e.cut) || e.tri[0] == kNone) continue;
    const Triangle& t = mesh.tris[e.tri[0]];
    TornSegment s{t.rest[cornerOf(t, e.v[0])], t.rest[cornerOf(t, e.v[1])]};
    if (s.b.x() < s.a.x() || (s.b.x() == s.a.x() && s.b.y() < s.a.y())) std::swap(s.a, s.b);
    segments.push_back(s);
  }
  // Each torn edge has a twin on the other lip with the same material segment: keep one.
  std::sort(segments.begin(), segments.end(), [](const TornSegment& p, const TornSegment& q) {
    return std::tie(p.a.x(), p.a.y(), p.b.x(), p.b.y()) < std::tie(q.a.x(), q.a.y(), q.b.x(), q.b.y());
  });
  std::vector<TornSegment> unique;
  for (const TornSegment& s : segments) {
    if (!unique.empty() && (unique.back().a - s.a).norm() < 1e-9 && (unique.back().b - s.b).norm() < 1e-9) continue;
    unique.push_back(s);
  }
  return unique;
}

// The segments whose middle lies in the box [lo, hi] (material space).
inline std::vector<TornSegment> segmentsInside(const std::vector<TornSegment>& segments, const Vec2& lo, const Vec2& hi) {
  std::vector<TornSegment> inside;
  for (const TornSegment& s : segments) {
    const Vec2 mid = 0.5 * (s.a + s.b);
    if ((mid.array() >= lo.array()).all() && (mid.array() <= hi.array()).all()) inside.push_back(s);
  }
  return inside;
}

inline double tornLength(const std::vector<TornSegment>& segments) {
  double sum = 0.0;
  for (const TornSegment& s : segments) sum += s.length();
  return sum;
}

// Share of the torn length whose direction lies within `toleranceDeg` of `directionDeg`.
inline double shareOfLengthWithin(const std::vector<TornSegment>& segments, double directionDeg, double toleranceDeg) {
  double near = 0.0;
  for (const TornSegment& s : segments) {
    if (lineAngleBetweenDeg(s.directionDeg(), directionDeg) <= toleranceDeg) near += s.length();
  }
  const double total = tornLength(segments);
  return total > 0.0 ? near / total : 0.0;
}

// A crack: a run of torn segments joined end to end where the crack neither branches nor turns by
// more than `maxTurnDeg` (two straight cracks linked by a short jog are two cracks and a jog), with
// its length and the direction of its principal axis (the line that best fits its segments,
// weighted by length).
struct Crack {
  double length = 0.0;
  double directionDeg = 0.0;
};

inline std::vector<Crack> cracks(const std::vector<TornSegment>& segments, double maxTurnDeg = 20.0) {
  // Segment ends meet where their material points agree to a tenth of a micrometre.
  std::map<std::pair<long long, long long>, std::vector<int>> at;  // point -> segments ending there
  auto key = [](const Vec2& p) { return std::make_pair(std::llround(p.x() * 1e7), std::llround(p.y() * 1e7)); };
  for (std::size_t k = 0; k < segments.size(); ++k) {
    at[key(segments[k].a)].push_back(static_cast<int>(k));
    at[key(segments[k].b)].push_back(static_cast<int>(k));
  }
  std::vector<int> parent(segments.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [point, ends] : at) {
    if (ends.size() != 2) continue;  // a crack's end, or a branch
    const double turn = lineAngleBetweenDeg(segments[ends[0]].directionDeg(), segments[ends[1]].directionDeg());
    if (turn <= maxTurnDeg) parent[root(ends[0])] = root(ends[1]);
  }
  std::map<int, std::vector<int>> members;
  for (std::size_t k = 0; k < segments.size(); ++k) members[root(static_cast<int>(k))].push_back(static_cast<int>(k));
  std::vector<Crack> out;
  for (const auto& [r, list] : members) {
    Mat2 tensor = Mat2::Zero();
    Crack crack;
    for (int k : list) {
      const Vec2 d = segments[k].b - segments[k].a;
      tensor += d * d.transpose() / std::max(d.norm(), 1e-300);
      crack.length += d.norm();
    }
    crack.directionDeg = 0.5 * std::atan2(2.0 * tensor(0, 1), tensor(0, 0) - tensor(1, 1)) * 180.0 / kPi;
    if (crack.directionDeg < 0.0) crack.directionDeg += 180.0;
    out.push_back(crack);
  }
  return out;
}

// Thesis §4.2, Figure 4.5 (Cloth 3): two vertical tears joined by a horizontal one, a flap. The
// torn length within 22.5 degrees of vertical is grouped along x (a group ends where no vertical
// segment's middle lies within `gap` of the next); the two longest groups are the two tears, and
// the join is the torn length within 22.5 degrees of horizontal whose middle lies between them.
struct FlapMeasure {
  double vertical = 0.0;              // m of torn length within 22.5 degrees of vertical
  double left = 0.0, right = 0.0;     // m in the two longest vertical groups (left one first)
  double separation = 0.0;            // m between those groups (their nearest middles)
  double joining = 0.0;               // m within 22.5 degrees of horizontal between them
};

inline FlapMeasure flapMeasure(const std::vector<TornSegment>& segments, double gap = 0.04) {
  std::vector<TornSegment> vertical;
  FlapMeasure out;
  for (const TornSegment& s : segments) {
    if (lineAngleBetweenDeg(s.directionDeg(), 90.0) <= 22.5) vertical.push_back(s);
  }
  out.vertical = tornLength(vertical);
  auto middle = [](const TornSegment& s) { return 0.5 * (s.a.x() + s.b.x()); };
  std::sort(vertical.begin(), vertical.end(),
            [&](const TornSegment& p, const TornSegment& q) { return middle(p) < middle(q); });
  struct Group {
    double lo = 0.0, hi = 0.0, length = 0.0;
  };
  std::vector<Group> groups;
  for (const TornSegment& s : vertical) {
    const double x = middle(s);
    if (groups.empty() || x - groups.back().hi > gap) groups.push_back(Group{x, x, 0.0});
    groups.back().hi = x;
    groups.back().length += s.length();
  }
  if (groups.size() < 2) {
    if (!groups.empty()) out.left = groups.front().length;
    return out;
  }
  std::sort(groups.begin(), groups.end(), [](const Group& p, const Group& q) { return p.length > q.length; });
  if (groups[1].lo < groups[0].lo) std::swap(groups[0], groups[1]);
  out.left = groups[0].length;
  out.right = groups[1].length;
  out.separation = groups[1].lo - groups[0].hi;
  for (const TornSegment& s : segments) {
    const double x = middle(s);
    if (lineAngleBetweenDeg(s.directionDeg(), 0.0) <= 22.5 && x > groups[0].hi && x < groups[1].lo) {
      out.joining += s.length();
    }
  }
  return out;
}

}  // namespace weft::gallery
