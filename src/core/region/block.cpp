#include "core/region/block.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

namespace autoblock {
namespace {

constexpr double kDegree = M_PI / 180.0;

}  // namespace

bool is_side_vertex(const Ring& ring, size_t i, const BlockRules& rules) {
  return std::fabs(interior_angle(ring, i) - M_PI) <= rules.flat_tolerance_degrees * kDegree;
}

std::optional<std::array<int, 4>> block_corners(const Region& region, const BlockRules& rules) {
  if (region.is_empty() || !region.holes().empty()) return std::nullopt;
  const Ring& ring = region.outer();
  std::array<int, 4> corners{};
  int count = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    if (is_side_vertex(ring, i, rules)) continue;
    const double angle = interior_angle(ring, i);
    if (angle > M_PI) return std::nullopt;                                              // reflex
    if (angle < rules.min_corner_degrees * kDegree || angle > rules.max_corner_degrees * kDegree) return std::nullopt;
    if (count == 4) return std::nullopt;
    corners[static_cast<size_t>(count++)] = static_cast<int>(i);
  }
  if (count != 4) return std::nullopt;
  return corners;
}

bool template_applies(const Region& region) { return region.is_convex(); }

std::vector<QuadPiece> template_pieces(const Region& region, const BlockRules& rules) {
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  // The template's corners: the part's corners (side vertices lie on the template's sides); all
  // vertices when fewer than three are corners.
  std::vector<size_t> corners;
  for (size_t i = 0; i < n; ++i) {
    if (!is_side_vertex(ring, i, rules)) corners.push_back(i);
  }
  if (corners.size() < 3) {
    corners.clear();
    for (size_t i = 0; i < n; ++i) corners.push_back(i);
  }
  const size_t m = corners.size();
  auto next = [n](size_t i) { return (i + 1) % n; };
  auto length = [](Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); };
  // Side k (corner k to corner k + 1) split at its midpoint by length: the boundary vertices before
  // it (from corner k), the midpoint, and the vertices after it (up to corner k + 1, exclusive).
  struct Split {
    std::vector<Point2> before, after;
    Point2 midpoint;
  };
  std::vector<Split> splits(m);
  const double q = region.quantum();
  for (size_t k = 0; k < m; ++k) {
    // The side's vertices, corner k to corner k + 1 inclusive, and their distances along it.
    std::vector<Point2> side{ring[corners[k]]};
    std::vector<double> at{0.0};
    for (size_t i = corners[k]; i != corners[(k + 1) % m]; i = next(i)) {
      side.push_back(ring[next(i)]);
      at.push_back(at.back() + length(ring[i], ring[next(i)]));
    }
    const double half = 0.5 * at.back();
    Split& s = splits[k];
    // A side vertex within the quantum of the midpoint is the midpoint.
    size_t on_vertex = 0;
    for (size_t v = 1; v + 1 < side.size(); ++v) {
      if (std::fabs(at[v] - half) <= q) on_vertex = v;
    }
    for (size_t v = 0; v + 1 < side.size(); ++v) {
      if (on_vertex != 0 ? v < on_vertex : at[v] < half) s.before.push_back(side[v]);
      else if (on_vertex != 0 ? v > on_vertex : true) s.after.push_back(side[v]);
    }
    if (on_vertex != 0) {
      s.midpoint = side[on_vertex];
    } else {
      size_t v = 0;
      while (v + 2 < side.size() && at[v + 1] < half) ++v;
      const double e = at[v + 1] - at[v];
      const double t = e > 0.0 ? (half - at[v]) / e : 0.0;
      s.midpoint = Point2{side[v].x + t * (side[v + 1].x - side[v].x), side[v].y + t * (side[v + 1].y - side[v].y)};
    }
  }
  const Point2 c = region.centroid();
  std::vector<QuadPiece> pieces;
  for (size_t k = 0; k < m; ++k) {
    const Split& out = splits[k];
    const Split& in = splits[(k + m - 1) % m];
    QuadPiece piece;
    piece.ring = out.before;  // corner k first
    piece.corners[1] = static_cast<int>(piece.ring.size());
    piece.ring.push_back(out.midpoint);
    piece.corners[2] = static_cast<int>(piece.ring.size());
    piece.ring.push_back(c);
    piece.corners[3] = static_cast<int>(piece.ring.size());
    piece.ring.push_back(in.midpoint);
    piece.ring.insert(piece.ring.end(), in.after.begin(), in.after.end());
    piece.corners[0] = 0;
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

std::vector<std::array<Point2, 4>> template_quads(const Region& region, const BlockRules& rules) {
  std::vector<std::array<Point2, 4>> quads;
  for (const QuadPiece& p : template_pieces(region, rules)) {
    quads.push_back({p.ring[static_cast<size_t>(p.corners[0])], p.ring[static_cast<size_t>(p.corners[1])],
                     p.ring[static_cast<size_t>(p.corners[2])], p.ring[static_cast<size_t>(p.corners[3])]});
  }
  return quads;
}

double scaled_jacobian_bound(const std::vector<Ring>& loops) {
  double bound = 1.0;
  for (const Ring& ring : loops) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Point2 prev = ring[(i + n - 1) % n], at = ring[i], next = ring[(i + 1) % n];
      // Interior angle for the region on the left: the turn from the incoming to the outgoing edge.
      const double in = std::atan2(at.y - prev.y, at.x - prev.x), out = std::atan2(next.y - at.y, next.x - at.x);
      double turn = out - in;
      while (turn <= -M_PI) turn += 2.0 * M_PI;
      while (turn > M_PI) turn -= 2.0 * M_PI;
      const double t = M_PI - turn;
      // sin(t / k) is largest for t / k nearest a right angle: k = floor or ceil of t / (pi / 2).
      const double k0 = std::max(1.0, std::floor(t / (0.5 * M_PI)));
      const double best = std::max(std::sin(t / k0), std::sin(t / (k0 + 1.0)));
      bound = std::min(bound, best);
    }
  }
  return bound;
}

OrientedRectangle min_area_rectangle(const Region& region) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_2> points, hull;
  for (const Point2& p : region.outer()) points.emplace_back(p.x, p.y);
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  // Rotating calipers: the minimum rectangle has a side along an edge of the hull. Coordinates are
  // taken relative to the hull's first vertex to keep digits for faces far from the origin.
  const double ox = hull[0].x(), oy = hull[0].y();
  OrientedRectangle best;
  double best_area = -1.0, best_tilt = 0.0;
  const size_t n = hull.size();
  for (size_t i = 0; i < n; ++i) {
    const double ex = hull[(i + 1) % n].x() - hull[i].x(), ey = hull[(i + 1) % n].y() - hull[i].y();
    const double len = std::hypot(ex, ey);
    if (len == 0.0) continue;
    double ux = ex / len, uy = ey / len;
    // Fold the axis into [0, 90) degrees: the same rectangle whichever of its sides is first.
    while (!(ux > 0.0 && uy >= 0.0)) {
      const double t = ux;
      ux = uy;
      uy = -t;
    }
    double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
    for (const K::Point_2& p : hull) {
      const double x = p.x() - ox, y = p.y() - oy;
      const double u = x * ux + y * uy, v = -x * uy + y * ux;
      umin = std::min(umin, u);
      umax = std::max(umax, u);
      vmin = std::min(vmin, v);
      vmax = std::max(vmax, v);
    }
    const double area = (umax - umin) * (vmax - vmin);
    const double tilt = std::min(std::atan2(uy, ux), M_PI / 2 - std::atan2(uy, ux));
    // Prefer the smaller area; within a relative 1e-12 of it, the axis nearest X or Y.
    if (best_area < 0.0 || area < best_area * (1.0 - 1e-12) || (area <= best_area * (1.0 + 1e-12) && tilt < best_tilt)) {
      best_area = area;
      best_tilt = tilt;
      const double cu = 0.5 * (umin + umax), cv = 0.5 * (vmin + vmax);
      best.center = {ox + cu * ux - cv * uy, oy + cu * uy + cv * ux};
      best.axis = {ux, uy};
      best.width = umax - umin;
      best.height = vmax - vmin;
    }
  }
  return best;
}

}  // namespace autoblock
