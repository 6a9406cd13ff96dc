#include "core/region/block.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

namespace autoblock {
namespace {

constexpr double kDegree = M_PI / 180.0;

}  // namespace

std::optional<std::array<int, 4>> block_corners(const Region& region, const BlockRules& rules) {
  if (region.is_empty() || !region.holes().empty()) return std::nullopt;
  const Ring& ring = region.outer();
  std::array<int, 4> corners{};
  int count = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const double angle = interior_angle(ring, i);
    if (std::fabs(angle - M_PI) <= rules.flat_tolerance_degrees * kDegree) continue;  // side vertex
    if (angle > M_PI) return std::nullopt;                                              // reflex
    if (angle < rules.min_corner_degrees * kDegree || angle > rules.max_corner_degrees * kDegree) return std::nullopt;
    if (count == 4) return std::nullopt;
    corners[static_cast<size_t>(count++)] = static_cast<int>(i);
  }
  if (count != 4) return std::nullopt;
  return corners;
}

bool template_applies(const Region& region) { return region.is_convex(); }

std::vector<std::array<Point2, 4>> template_quads(const Region& region) {
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  const Point2 c = region.centroid();
  auto mid = [&](size_t i) {
    const Point2 a = ring[i % n], b = ring[(i + 1) % n];
    return Point2{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  };
  std::vector<std::array<Point2, 4>> quads;
  for (size_t i = 0; i < n; ++i) quads.push_back({ring[i], mid(i), c, mid(i + n - 1)});
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
