#include "core/region/region_observation.h"

#include <cmath>
#include <stdexcept>

namespace autoblock {
namespace {

constexpr double kPi = 3.14159265358979323846;

const Ring& checked_loop(const Region& region, int loop, int index) {
  if (loop < 0 || loop >= region.loop_count()) throw std::out_of_range("observe_region_vertex: no such loop");
  const Ring& ring = region.loop(loop);
  if (index < 0 || static_cast<size_t>(index) >= ring.size()) throw std::out_of_range("observe_region_vertex: no such vertex");
  return ring;
}

}  // namespace

double region_interior_angle(const Region& region, int loop, int index) {
  const Ring& ring = checked_loop(region, loop, index);
  const size_t n = ring.size(), i = static_cast<size_t>(index);
  const Point2 v = ring[i], p = ring[(i + n - 1) % n], q = ring[(i + 1) % n];
  const double ax = q.x - v.x, ay = q.y - v.y, bx = p.x - v.x, by = p.y - v.y;
  double angle = std::atan2(ax * by - ay * bx, ax * bx + ay * by) * 180.0 / kPi;
  if (angle <= 0.0) angle += 360.0;
  return angle;
}

Observation observe_region_vertex(const Region& region, int loop, int index) {
  const Ring& ring = checked_loop(region, loop, index);
  const size_t n = ring.size(), i = static_cast<size_t>(index);
  const Point2 v = ring[i], p = ring[(i + n - 1) % n], q = ring[(i + 1) % n];
  const Point2 c = region.centroid();
  const Box box = region.bbox();
  const double s = box.longer_side();
  auto f = [](double value) { return static_cast<float>(value); };
  return Observation{f((p.x - v.x) / s), f((p.y - v.y) / s), f((q.x - v.x) / s), f((q.y - v.y) / s),
                     f((c.x - v.x) / s), f((c.y - v.y) / s), f(region_interior_angle(region, loop, index) / 360.0),
                     f(box.width() / s), f(box.height() / s)};
}

}  // namespace autoblock
