#include "core/region/region_reward.h"

#include <algorithm>
#include <cmath>

namespace autoblock {
namespace {

double quad_area(const std::array<Point2, 4>& q) {
  double a = 0.0;
  for (size_t i = 0; i < 4; ++i) a += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
  return 0.5 * a;
}

}  // namespace

double region_cut_reward(RewardPreset preset, const CutOutcome& outcome, double face_size, const BlockRules& rules) {
  const std::vector<Region>& pieces = outcome.pieces;
  if (preset == RewardPreset::Mesh) {
    if (pieces.size() == 1) return -3.0;
    double cost = static_cast<double>(pieces.size() - 1);
    for (const Region& piece : pieces) {
      if (is_block(piece, rules)) cost += kMeshThinWeight * std::log(min_area_rectangle(piece).aspect_ratio());
    }
    double j_new = 1.0;
    for (const Region& piece : pieces) {
      for (int k = 0; k < piece.loop_count(); ++k) {
        const Ring& ring = piece.loop(k);
        for (size_t i = 0; i < ring.size(); ++i) {
          const Point2 v = ring[i];
          const bool on_chord = std::any_of(outcome.chords.begin(), outcome.chords.end(),
                                            [&](const Chord& c) { return c.a == v || c.b == v; });
          if (!on_chord) continue;
          const double angle = interior_angle(ring, i);
          if (is_side_vertex(ring, i, rules) || angle > M_PI) continue;
          j_new = std::min(j_new, std::sin(angle));
        }
      }
    }
    return -cost - kMeshShapeWeight * (1.0 - j_new);
  }
  const double scale = 1.0 / (face_size * face_size);
  std::vector<double> areas, ratios;
  int blocks = 0;
  for (const Region& piece : pieces) {
    areas.push_back(piece.area() * scale);
    ratios.push_back(min_area_rectangle(piece).aspect_ratio());
    if (is_block(piece, rules)) ++blocks;
  }
  return equation_one(areas, ratios, blocks);
}

double region_template_reward(RewardPreset preset, const Region& part, double face_size, const BlockRules& rules) {
  const auto quads = template_quads(part);
  if (preset == RewardPreset::Mesh) {
    // The shape term for the corners the template creates (at its feet and its centre) and for the
    // part's corners it keeps whole that a block could not have (above the rules' largest corner;
    // the part's other corners were paid for by the cuts that made them, or are the face's).
    double j_new = 1.0;
    for (const auto& q : quads) {
      const Point2 corner = q[0], next = q[1], prev = q[3];
      const double ux = next.x - corner.x, uy = next.y - corner.y, wx = prev.x - corner.x, wy = prev.y - corner.y;
      const double angle = std::atan2(ux * wy - uy * wx, ux * wx + uy * wy) * 180.0 / M_PI;
      if (angle > rules.max_corner_degrees) j_new = std::min(j_new, std::sin(angle * M_PI / 180.0));
      for (size_t k = 1; k < 4; ++k) {
        const Point2 v = q[k], next = q[(k + 1) % 4], prev = q[(k + 3) % 4];
        const double ax = next.x - v.x, ay = next.y - v.y, bx = prev.x - v.x, by = prev.y - v.y;
        const double length = std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
        j_new = std::min(j_new, length > 0.0 ? (ax * by - ay * bx) / length : -1.0);
      }
    }
    return -static_cast<double>(quads.size() - 1) - kTemplatePenalty - kMeshShapeWeight * (1.0 - j_new);
  }
  const double scale = 1.0 / (face_size * face_size);
  std::vector<double> areas, ratios;
  for (const auto& q : quads) {
    areas.push_back(quad_area(q) * scale);
    const Region r(Ring(q.begin(), q.end()), {}, part.quantum());
    ratios.push_back(r.is_empty() ? 1.0 : min_area_rectangle(r).aspect_ratio());
  }
  return equation_one(areas, ratios, static_cast<int>(quads.size())) - kTemplatePenalty;
}

}  // namespace autoblock
