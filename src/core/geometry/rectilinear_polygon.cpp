#include "core/geometry/rectilinear_polygon.h"

#include <algorithm>
#include <cmath>

namespace autoblock {

double signed_area(const Ring& ring) {
  double twice = 0.0;
  const size_t n = ring.size();
  for (size_t k = 0; k < n; ++k) {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % n];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

double polygon_area(const RectilinearPolygon& polygon) {
  double area = std::fabs(signed_area(polygon.outer));
  for (const Ring& hole : polygon.holes) area -= std::fabs(signed_area(hole));
  return area;
}

Box ring_bbox(const Ring& ring) {
  Box box{ring[0].x, ring[0].y, ring[0].x, ring[0].y};
  for (const Point2& p : ring) {
    box.xmin = std::min(box.xmin, p.x);
    box.xmax = std::max(box.xmax, p.x);
    box.ymin = std::min(box.ymin, p.y);
    box.ymax = std::max(box.ymax, p.y);
  }
  return box;
}

bool point_in_ring(Point2 p, const Ring& ring) {
  bool inside = false;
  const size_t n = ring.size();
  for (size_t k = 0, prev = n - 1; k < n; prev = k++) {
    const Point2& a = ring[k];
    const Point2& b = ring[prev];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

}  // namespace autoblock
