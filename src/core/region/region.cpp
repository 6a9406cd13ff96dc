#include "core/region/region.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

namespace autoblock {
namespace {

double cross(Point2 o, Point2 a, Point2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool lower_left(Point2 a, Point2 b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }

// Rotates the ring so that it starts at its lowest, then leftmost vertex.
void rotate_to_start(Ring* ring) {
  if (ring->empty()) return;
  auto first = std::min_element(ring->begin(), ring->end(), lower_left);
  std::rotate(ring->begin(), first, ring->end());
}

void hash_combine(size_t* seed, double value) {
  if (value == 0.0) value = 0.0;  // -0.0 and 0.0 are the same coordinate
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  *seed ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ull + (*seed << 6) + (*seed >> 2);
}

}  // namespace

std::vector<Ring> Region::loops() const {
  std::vector<Ring> all{outer_};
  all.insert(all.end(), holes_.begin(), holes_.end());
  return all;
}

double segment_distance_squared(Point2 x, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((x.x - a.x) * dx + (x.y - a.y) * dy) / len2 : 0.0;
  t = std::max(0.0, std::min(1.0, t));
  const double ex = x.x - (a.x + t * dx), ey = x.y - (a.y + t * dy);
  return ex * ex + ey * ey;
}

double segment_distance(Point2 x, Point2 a, Point2 b) { return std::sqrt(segment_distance_squared(x, a, b)); }

double region_perimeter(const Region& region) {
  double length = 0.0;
  for (int k = 0; k < region.loop_count(); ++k) {
    const Ring& ring = region.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) {
      const double dx = ring[(i + 1) % ring.size()].x - ring[i].x, dy = ring[(i + 1) % ring.size()].y - ring[i].y;
      length += std::sqrt(dx * dx + dy * dy);
    }
  }
  return length;
}

double snap_to_lattice(double value, double quantum) {
  const double snapped = std::round(value / quantum) * quantum;
  return snapped == 0.0 ? 0.0 : snapped;
}

// Merges consecutive equal points, the last with the first too.
static void merge_equal_points(Ring* ring) {
  ring->erase(std::unique(ring->begin(), ring->end()), ring->end());
  while (ring->size() > 1 && ring->front() == ring->back()) ring->pop_back();
}

Ring canonical_ring(const Ring& ring, double quantum) {
  Ring out;
  out.reserve(ring.size());
  for (const Point2& p : ring) out.push_back({snap_to_lattice(p.x, quantum), snap_to_lattice(p.y, quantum)});
  merge_equal_points(&out);
  // Remove every vertex v (neighbours p and n) within one quantum of the line through p and n (a
  // collinear vertex, or the tip of a spike of zero width), and every tip of a wedge thinner than one
  // quantum (p within one quantum of the edge v-n, or n of the edge v-p), one at a time, until none
  // is left.
  // After a removal the scan resumes at the vertex before it (the vertices before that keep their
  // neighbours), or starts over when the removal touched the ring's wrap or merged points: the same
  // removals, in the same order, as starting over every time.
  const double q2 = quantum * quantum;
  size_t i = 0;
  while (out.size() >= 3 && i < out.size()) {
    const size_t m = out.size();
    const Point2 p = out[(i + m - 1) % m], v = out[i], n = out[(i + 1) % m];
    // Squared comparisons: no square roots on this hot path. A point farther than one quantum from
    // a segment's line (|cross| over the segment's length) is farther from the segment too.
    const double len2 = (n.x - p.x) * (n.x - p.x) + (n.y - p.y) * (n.y - p.y), c = cross(p, v, n), c2 = c * c;
    const double vn2 = (n.x - v.x) * (n.x - v.x) + (n.y - v.y) * (n.y - v.y),
                 vp2 = (p.x - v.x) * (p.x - v.x) + (p.y - v.y) * (p.y - v.y);
    const bool remove = len2 == 0.0 || c2 <= q2 * len2 || (c2 <= q2 * vn2 && segment_distance_squared(p, v, n) <= q2) ||
                        (c2 <= q2 * vp2 && segment_distance_squared(n, v, p) <= q2);
    if (!remove) {
      ++i;
      continue;
    }
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
    merge_equal_points(&out);
    i = (out.size() + 1 == m && i != 0 && i != m - 1) ? i - 1 : 0;
  }
  if (out.size() < 3 || signed_area(out) == 0.0) return {};
  return out;
}

double interior_angle(const Ring& ring, size_t i) {
  const size_t n = ring.size();
  const Point2 p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
  // Angle from the direction to the next vertex, turning counter-clockwise, to the direction to the
  // previous one: the region lies on the ring's left, so that is the interior angle.
  // One atan2 of the two directions' cross and dot products (in (-pi, pi]), then into (0, 2 pi].
  const double ax = q.x - v.x, ay = q.y - v.y, bx = p.x - v.x, by = p.y - v.y;
  double angle = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  if (angle <= 0.0) angle += 2.0 * M_PI;
  return angle;
}

bool is_reflex_vertex(const Ring& ring, size_t i) {
  const size_t n = ring.size();
  const Point2 p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
  const double ax = q.x - v.x, ay = q.y - v.y, bx = p.x - v.x, by = p.y - v.y;
  const double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
  // interior_angle is atan2(cross, dot) taken into (0, 2 pi]: above pi for a negative cross
  // product, and 2 pi for a spike (cross 0, dot > 0); exactly pi for cross 0, dot < 0.
  return cross < 0.0 || (cross == 0.0 && dot >= 0.0);
}

Point2 ring_centroid(const Ring& ring) {
  double a = 0.0, cx = 0.0, cy = 0.0;
  const size_t n = ring.size();
  // Relative to the first vertex, so that faces far from the origin keep their digits.
  const Point2 o = ring.empty() ? Point2{} : ring[0];
  for (size_t i = 0; i < n; ++i) {
    const Point2 p{ring[i].x - o.x, ring[i].y - o.y};
    const Point2 q{ring[(i + 1) % n].x - o.x, ring[(i + 1) % n].y - o.y};
    const double c = p.x * q.y - q.x * p.y;
    a += c;
    cx += (p.x + q.x) * c;
    cy += (p.y + q.y) * c;
  }
  if (a == 0.0) {
    Point2 mean;
    for (const Point2& p : ring) mean = {mean.x + p.x / n, mean.y + p.y / n};
    return mean;
  }
  return {o.x + cx / (3.0 * a), o.y + cy / (3.0 * a)};
}

Region::Region(const Ring& outer, const std::vector<Ring>& holes, double quantum) : quantum_(quantum) {
  outer_ = canonical_ring(outer, quantum);
  if (outer_.empty()) return;
  if (signed_area(outer_) < 0.0) std::reverse(outer_.begin(), outer_.end());
  rotate_to_start(&outer_);
  for (const Ring& hole : holes) {
    Ring h = canonical_ring(hole, quantum);
    if (h.empty()) continue;
    if (signed_area(h) > 0.0) std::reverse(h.begin(), h.end());
    rotate_to_start(&h);
    holes_.push_back(std::move(h));
  }
  std::sort(holes_.begin(), holes_.end(), [](const Ring& a, const Ring& b) {
    return lower_left(a[0], b[0]) || (a[0] == b[0] && a.size() < b.size());
  });
  // Area: outer minus holes.
  double a = signed_area(outer_);
  for (const Ring& h : holes_) a += signed_area(h);  // negative
  area_ = a;
  size_t seed = outer_.size();
  for (int k = 0; k < loop_count(); ++k) {
    for (const Point2& p : loop(k)) {
      hash_combine(&seed, p.x);
      hash_combine(&seed, p.y);
    }
    hash_combine(&seed, -1.0 - k);
  }
  hash_ = seed;
}

Point2 Region::centroid() const {
  // Outer minus holes, each loop's centroid weighted by its signed area.
  const double outer_area = signed_area(outer_);
  const Point2 c0 = ring_centroid(outer_);
  double a = outer_area, mx = c0.x * outer_area, my = c0.y * outer_area;
  for (const Ring& h : holes_) {
    const double ha = signed_area(h);  // negative
    const Point2 ch = ring_centroid(h);
    a += ha;
    mx += ch.x * ha;
    my += ch.y * ha;
  }
  return a > 0.0 ? Point2{mx / a, my / a} : c0;
}

int Region::vertex_count() const {
  int n = 0;
  for (int k = 0; k < loop_count(); ++k) n += static_cast<int>(loop(k).size());
  return n;
}

bool Region::is_convex() const {
  if (!holes_.empty() || is_empty()) return false;
  const size_t n = outer_.size();
  for (size_t i = 0; i < n; ++i) {
    if (cross(outer_[(i + n - 1) % n], outer_[i], outer_[(i + 1) % n]) < 0.0) return false;
  }
  return true;
}

bool Region::operator==(const Region& other) const {
  return hash_ == other.hash_ && outer_.size() == other.outer_.size() && holes_.size() == other.holes_.size() &&
         std::equal(outer_.begin(), outer_.end(), other.outer_.begin()) &&
         std::equal(holes_.begin(), holes_.end(), other.holes_.begin(),
                    [](const Ring& a, const Ring& b) { return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin()); });
}

}  // namespace autoblock
