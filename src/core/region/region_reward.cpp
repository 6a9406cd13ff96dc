#include "core/region/region_reward.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace autoblock {
namespace {

double quad_area(const std::array<Point2, 4>& q) {
  double a = 0.0;
  for (size_t i = 0; i < 4; ++i) a += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
  return 0.5 * a;
}

}  // namespace

double block_taper(const Region& block, const std::array<int, 4>& corners) {
  const Ring& ring = block.outer();
  const size_t n = ring.size();
  std::array<double, 4> side{};
  for (size_t k = 0; k < 4; ++k) {
    for (size_t i = static_cast<size_t>(corners[k]); i != static_cast<size_t>(corners[(k + 1) % 4]); i = (i + 1) % n) {
      side[k] += std::hypot(ring[(i + 1) % n].x - ring[i].x, ring[(i + 1) % n].y - ring[i].y);
    }
  }
  auto ratio = [](double a, double b) { return std::max(a, b) / std::max(std::min(a, b), 1e-300); };
  return std::max(ratio(side[0], side[2]), ratio(side[1], side[3]));
}

double block_taper_cost(const Region& block, const std::array<int, 4>& corners) {
  const double taper = block_taper(block, corners);
  return taper > kMeshTaperFrom ? kMeshTaperWeight * std::log(taper / kMeshTaperFrom) : 0.0;
}

double pieces_taper_cost(const std::vector<Region>& pieces, const BlockRules& rules) {
  double cost = 0.0;
  if (pieces.size() < 2) return cost;
  for (const Region& piece : pieces) {
    if (const std::optional<std::array<int, 4>> corners = block_corners(piece, rules)) cost += block_taper_cost(piece, *corners);
  }
  return cost;
}

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

namespace {

// The angle from u counter-clockwise to w, in (0, 2 pi].
double ccw_angle(Point2 u, Point2 w) {
  double angle = std::atan2(u.x * w.y - u.y * w.x, u.x * w.x + u.y * w.y);
  if (angle <= 0.0) angle += 2.0 * M_PI;
  return angle;
}

double length(Point2 u) { return std::sqrt(u.x * u.x + u.y * u.y); }

}  // namespace

double region_cut_reward_bound(RewardPreset preset, const Region& part, const std::vector<Chord>& chords,
                               const BlockRules& rules) {
  if (preset != RewardPreset::Mesh || chords.empty() || !part.holes().empty()) return std::numeric_limits<double>::infinity();
  const Ring& ring = part.outer();
  const size_t n = ring.size();
  // A full cut's line can run along an edge of the part between two chords (it touches the boundary
  // there): such a chord is that edge and separates nothing. Every other chord crosses the part's
  // interior from boundary to boundary, and a part without holes is simply connected: each such
  // chord adds one piece. N pieces cost N - 1; the other terms are <= 0.
  std::vector<const Chord*> crossing;
  for (const Chord& c : chords) {
    bool edge = false;
    for (size_t i = 0; i < n && !edge; ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % n];
      edge = (c.a == a && c.b == b) || (c.a == b && c.b == a);
    }
    if (!edge) crossing.push_back(&c);
  }
  if (crossing.empty()) return std::numeric_limits<double>::infinity();
  if (crossing.size() > 1) return -static_cast<double>(crossing.size());
  const double q = part.quantum();
  // A corner at or above this (within the margin) may be a side vertex or reflex: it counts 1.
  const double side_from = M_PI - rules.flat_tolerance_degrees * M_PI / 180.0;
  double j = 1.0;
  const Chord& c = *crossing.front();
  for (int end = 0; end < 2; ++end) {
    const Point2 e = end == 0 ? c.a : c.b, other = end == 0 ? c.b : c.a;
    const Point2 d{other.x - e.x, other.y - e.y};
    const double chord_length = length(d);
    if (!(chord_length > 0.0)) return std::numeric_limits<double>::infinity();
    size_t vertex = n, edge = n;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < n && vertex == n; ++i) {
      if (ring[i] == e) vertex = i;
      const double distance = segment_distance_squared(e, ring[i], ring[(i + 1) % n]);
      if (distance < nearest) {
        nearest = distance;
        edge = i;
      }
    }
    // Rounding the pieces to the lattice moves each end by under a quantum: the angles at this end
    // change by at most about q over the chord's and the edges' lengths (radians; sine is 1-Lipschitz).
    std::vector<double> angles;
    double shortest = chord_length;
    if (vertex < n) {
      const Point2 p = ring[(vertex + n - 1) % n], v = ring[vertex], nx = ring[(vertex + 1) % n];
      const Point2 out{nx.x - v.x, nx.y - v.y}, in{p.x - v.x, p.y - v.y};
      shortest = std::min({shortest, length(out), length(in)});
      angles = {ccw_angle(out, d), ccw_angle(d, in)};
    } else {
      if (edge == n) return std::numeric_limits<double>::infinity();
      const Point2 a = ring[edge], b = ring[(edge + 1) % n];
      const Point2 t{b.x - a.x, b.y - a.y};
      shortest = std::min({shortest, length({e.x - a.x, e.y - a.y}), length({b.x - e.x, b.y - e.y})});
      const double theta = ccw_angle(t, d);
      angles = {theta, M_PI - theta};
    }
    if (!(shortest > 0.0)) return std::numeric_limits<double>::infinity();
    const double margin = 4.0 * q / shortest + 1e-9;
    for (const double angle : angles) {
      if (!(angle > 0.0) || angle >= side_from - margin) continue;  // perhaps a side vertex, or reflex: 1
      j = std::min(j, std::sin(angle) + margin);
    }
  }
  return -1.0 - kMeshShapeWeight * (1.0 - std::min(1.0, j));
}

double region_template_reward(RewardPreset preset, const Region& part, double face_size, const BlockRules& rules) {
  if (preset == RewardPreset::Mesh && !part.holes().empty()) {
    // The O-grid (block.h): its corner and side pieces' corners are its own (right angles on a
    // rectangle); a ring piece meets the hole at the angle its spoke makes with the hole's tangent
    // there (the direction between the hole vertex's neighbours), and its box corners are the
    // five-valent vertices every quad mesh of the part needs, whose best is sin 72 degrees
    // (topology_jacobian_bound), what smoothing works towards.
    const Ring& hole = part.holes()[0];
    // A tight cell's O-grid (four ring pieces, the part's sides its box) spokes from the part's corners,
    // whose angles are what they are.
    const std::vector<QuadPiece> pieces = template_pieces(part, rules);
    const bool tight = pieces.size() == 4;
    double j_new = 1.0;
    for (size_t p = 0; p < pieces.size(); ++p) {
      const QuadPiece& piece = pieces[p];
      const bool ring_piece = p + 4 >= pieces.size();
      for (int k = 0; k < 4; ++k) {
        const double j = piece_corner_angle(piece, k).sine;
        if (ring_piece && k < 2) {
          j_new = std::min(j_new, j > 0.0 && !tight ? std::sin(0.4 * M_PI) : j);
        } else if (ring_piece) {
          // The hole's vertex: its spoke runs to the box corner before it (k = 2) or after it (k = 3).
          const Point2 v = piece.ring[static_cast<size_t>(piece.corners[static_cast<size_t>(k)])];
          const Point2 spoke = piece.ring[static_cast<size_t>(piece.corners[k == 2 ? 1 : 0])];
          const size_t at = static_cast<size_t>(std::find(hole.begin(), hole.end(), v) - hole.begin());
          if (at == hole.size()) throw std::logic_error("region_template_reward: an O-grid spoke ends off the hole");
          const Point2 before = hole[(at + hole.size() - 1) % hole.size()], after = hole[(at + 1) % hole.size()];
          const double tx = after.x - before.x, ty = after.y - before.y, sx = spoke.x - v.x, sy = spoke.y - v.y;
          const double l = std::sqrt((tx * tx + ty * ty) * (sx * sx + sy * sy));
          j_new = std::min(j_new, l > 0.0 ? std::fabs(tx * sy - ty * sx) / l : 0.0);
        } else {
          j_new = std::min(j_new, j);
        }
      }
    }
    return -static_cast<double>(pieces.size() - 1) - kMeshShapeWeight * (1.0 - j_new);
  }
  const auto quads = template_quads(part);
  if (preset == RewardPreset::Mesh) {
    // The shape term for the corners the template creates (at its feet and its centre) and for the
    // part's corners it keeps whole that a block could not have (above the rules' largest corner;
    // the part's other corners were paid for by the cuts that made them, or are the face's).
    // On a part with a concave arc (the corner piece of a reflex fillet, block.h) the template's centre
    // is the five-valent vertex the part needs; the arc takes some of the turn around it (45 degrees
    // beside a quarter arc), which smoothing gives back, as at an O-grid's box corners: its best is
    // sin 72 degrees.
    const bool five_valent = quads.size() == 5 && !part.is_convex() && !concave_runs(part.outer()).empty();
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
        const double j = length > 0.0 ? (ax * by - ay * bx) / length : -1.0;
        j_new = std::min(j_new, five_valent && k == 2 && j > 0.0 ? std::sin(0.4 * M_PI) : j);
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
