#include "core/env/observation.h"

namespace autoblock {

Observation observe_vertex(const Part& part, const std::vector<CornerRing>& loops, int loop, int index) {
  const Grid& grid = part.grid();
  const CornerRing& ring = loops[static_cast<size_t>(loop)];
  const int n = static_cast<int>(ring.size());
  auto position = [&grid](const Corner& c) {
    return Point2{grid.xs[static_cast<size_t>(c.i)], grid.ys[static_cast<size_t>(c.j)]};
  };
  const Corner& corner = ring[static_cast<size_t>(index)];
  const Point2 v = position(corner);
  const Point2 p = position(ring[static_cast<size_t>((index + n - 1) % n)]);
  const Point2 q = position(ring[static_cast<size_t>((index + 1) % n)]);
  const Point2 c = part.centroid();
  const Box box = part.bbox();
  const double s = box.longer_side();
  auto f = [](double value) { return static_cast<float>(value); };
  return Observation{f((p.x - v.x) / s), f((p.y - v.y) / s), f((q.x - v.x) / s), f((q.y - v.y) / s),
                     f((c.x - v.x) / s), f((c.y - v.y) / s), corner.reflex ? 0.75f : 0.25f,
                     f(box.width() / s), f(box.height() / s)};
}

}  // namespace autoblock
