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

std::vector<std::array<Point2, 4>> template_quads(const Region& region, const BlockRules& rules) {
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
  // The midpoint, by length along the boundary, of the side from corner k to corner k + 1.
  auto side_midpoint = [&](size_t k) {
    const size_t from = corners[k], to = corners[(k + 1) % corners.size()];
    double length = 0.0;
    for (size_t i = from; i != to; i = (i + 1) % n) length += std::hypot(ring[(i + 1) % n].x - ring[i].x, ring[(i + 1) % n].y - ring[i].y);
    double left = 0.5 * length;
    for (size_t i = from;; i = (i + 1) % n) {
      const Point2 a = ring[i], b = ring[(i + 1) % n];
      const double e = std::hypot(b.x - a.x, b.y - a.y);
      if (left <= e || (i + 1) % n == to) {
        const double t = e > 0.0 ? std::min(1.0, left / e) : 0.0;
        return Point2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
      }
      left -= e;
    }
  };
  const Point2 c = region.centroid();
  std::vector<Point2> mids;
  for (size_t k = 0; k < corners.size(); ++k) mids.push_back(side_midpoint(k));
  std::vector<std::array<Point2, 4>> quads;
  for (size_t k = 0; k < corners.size(); ++k) {
    quads.push_back({ring[corners[k]], mids[k], c, mids[(k + corners.size() - 1) % corners.size()]});
  }
  return quads;
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
