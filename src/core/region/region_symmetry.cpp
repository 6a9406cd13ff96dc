#include "core/region/region_symmetry.h"

#include <cmath>
#include <vector>

namespace autoblock {

Region transform_region(const Region& region, double angle, bool mirror) {
  if (angle == 0.0 && !mirror) return region;
  const Box box = region.bbox();
  // On the lattice, so that a mirror or a quarter turn alone maps lattice points onto lattice points.
  const double q = region.quantum();
  const Point2 centre{snap_to_lattice(0.5 * (box.xmin + box.xmax), q), snap_to_lattice(0.5 * (box.ymin + box.ymax), q)};
  const double c = std::cos(angle), s = std::sin(angle);
  auto move = [&](const Ring& ring) {
    Ring out;
    out.reserve(ring.size());
    for (const Point2& p : ring) {
      const double x = mirror ? centre.x - p.x : p.x - centre.x, y = p.y - centre.y;
      out.push_back({centre.x + c * x - s * y, centre.y + s * x + c * y});
    }
    return out;  // a mirror reverses the orientation; Region's constructor restores it
  };
  std::vector<Ring> holes;
  for (const Ring& hole : region.holes()) holes.push_back(move(hole));
  return Region(move(region.outer()), holes, region.quantum());
}

}  // namespace autoblock
