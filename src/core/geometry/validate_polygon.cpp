#include "core/geometry/validate_polygon.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/geometry/tolerance.h"

namespace autoblock {
namespace {

// Coordinates in messages are rounded to the face's tolerance: noise below it reads 0.
std::string edge_text(const Point2& a, const Point2& b, double tol) {
  return "from " + format_point(a.x, a.y, tol) + " to " + format_point(b.x, b.y, tol);
}

// Removes vertices between collinear edges; throws when the boundary doubles back on itself.
Ring merge_collinear(Ring ring, const std::string& name, double tol) {
  bool changed = true;
  while (changed && ring.size() >= 3) {
    changed = false;
    const size_t n = ring.size();
    for (size_t k = 0; k < n; ++k) {
      const Point2& prev = ring[(k + n - 1) % n];
      const Point2& cur = ring[k];
      const Point2& next = ring[(k + 1) % n];
      const bool in_x = prev.y == cur.y, out_x = cur.y == next.y;
      if (in_x != out_x) continue;
      const double in = in_x ? cur.x - prev.x : cur.y - prev.y;
      const double out = in_x ? next.x - cur.x : next.y - cur.y;
      if ((in > 0) != (out > 0)) {
        throw InputError("the " + name + " doubles back on itself at " + format_point(cur.x, cur.y, tol));
      }
      ring.erase(ring.begin() + static_cast<long>(k));
      changed = true;
      break;
    }
  }
  if (ring.size() < 4) throw InputError("the " + name + " encloses no area");
  return ring;
}

struct Segment {
  Point2 a, b;  // a <= b along the segment's axis
  bool horizontal;
  int ring;
  size_t index;  // edge index within the ring
};

Segment make_segment(const Point2& p, const Point2& q, int ring, size_t index) {
  Segment s{p, q, p.y == q.y, ring, index};
  if (s.horizontal ? s.a.x > s.b.x : s.a.y > s.b.y) std::swap(s.a, s.b);
  return s;
}

// Closed segments s and t share a point: returns true and that point (the first one for overlaps).
bool segments_meet(const Segment& s, const Segment& t, Point2* where) {
  if (s.horizontal == t.horizontal) {
    if (s.horizontal ? s.a.y != t.a.y : s.a.x != t.a.x) return false;
    const double lo = s.horizontal ? std::max(s.a.x, t.a.x) : std::max(s.a.y, t.a.y);
    const double hi = s.horizontal ? std::min(s.b.x, t.b.x) : std::min(s.b.y, t.b.y);
    if (lo > hi) return false;
    *where = s.horizontal ? Point2{lo, s.a.y} : Point2{s.a.x, lo};
    return true;
  }
  const Segment& h = s.horizontal ? s : t;
  const Segment& v = s.horizontal ? t : s;
  if (v.a.x < h.a.x || v.a.x > h.b.x || h.a.y < v.a.y || h.a.y > v.b.y) return false;
  *where = Point2{v.a.x, h.a.y};
  return true;
}

void check_no_contact(const std::vector<Ring>& rings, const std::vector<std::string>& names, double tol) {
  std::vector<Segment> segments;
  for (size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = rings[r];
    for (size_t k = 0; k < ring.size(); ++k) {
      segments.push_back(make_segment(ring[k], ring[(k + 1) % ring.size()], static_cast<int>(r), k));
    }
  }
  // Sweep over x: only segments whose x-ranges overlap can meet.
  std::stable_sort(segments.begin(), segments.end(),
                   [](const Segment& s, const Segment& t) { return s.a.x < t.a.x; });
  for (size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    for (size_t j = i + 1; j < segments.size() && segments[j].a.x <= s.b.x; ++j) {
      const Segment& t = segments[j];
      if (s.ring == t.ring) {
        const size_t n = rings[static_cast<size_t>(s.ring)].size();
        const bool adjacent = (s.index + 1) % n == t.index || (t.index + 1) % n == s.index;
        if (adjacent) continue;  // they share their common corner only (spikes were rejected)
      }
      Point2 where;
      if (!segments_meet(s, t, &where)) continue;
      const Segment& h = s.horizontal ? s : t;
      const Segment& v = s.horizontal ? t : s;
      const bool crossing = s.horizontal != t.horizontal && where.x > h.a.x && where.x < h.b.x && where.y > v.a.y &&
                            where.y < v.b.y;
      const std::string what = crossing ? "crosses" : "touches";
      const Segment& first = s.ring <= t.ring ? s : t;
      const Segment& second = s.ring <= t.ring ? t : s;
      const std::string subject =
          s.ring == t.ring ? "the " + names[static_cast<size_t>(s.ring)] + " " + what + " itself"
                           : "the " + names[static_cast<size_t>(first.ring)] + " " + what + " the " +
                                 names[static_cast<size_t>(second.ring)];
      throw InputError(subject + " at " + format_point(where.x, where.y, tol) + " (edges " +
                       edge_text(first.a, first.b, tol) + " and " + edge_text(second.a, second.b, tol) + ")");
    }
  }
}

}  // namespace

std::map<double, double> snap_map(std::vector<double> values, double tol) {
  std::sort(values.begin(), values.end());
  std::map<double, double> snapped;
  size_t start = 0;
  for (size_t k = 1; k <= values.size(); ++k) {
    if (k == values.size() || values[k] - values[k - 1] > tol) {
      double sum = 0.0;
      for (size_t m = start; m < k; ++m) sum += values[m];
      const double mean = sum / static_cast<double>(k - start);
      for (size_t m = start; m < k; ++m) snapped[values[m]] = mean;
      start = k;
    }
  }
  return snapped;
}

double face_tolerance(const std::vector<RawRing>& raw) {
  if (raw.empty()) throw InputError("the face has no boundary wire");
  Box box{};
  bool first = true;
  for (const RawRing& ring : raw) {
    if (ring.points.size() < 3) {
      throw InputError("the face has zero or tiny area: the " + ring.name + " has only " +
                       counted(static_cast<long long>(ring.points.size()), "straight edge"));
    }
    for (const Point2& p : ring.points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        throw InputError("the " + ring.name + " has a vertex with a coordinate that is not a finite number");
      }
      if (std::fabs(p.x) > kMaximumCoordinate || std::fabs(p.y) > kMaximumCoordinate) {
        throw InputError("the " + ring.name + " has a vertex at " + format_point(p.x, p.y) +
                         ": coordinates beyond " + format_number(kMaximumCoordinate) + " are not supported");
      }
      if (first) box = Box{p.x, p.y, p.x, p.y};
      first = false;
      box.xmin = std::min(box.xmin, p.x);
      box.xmax = std::max(box.xmax, p.x);
      box.ymin = std::min(box.ymin, p.y);
      box.ymax = std::max(box.ymax, p.y);
    }
  }
  const double size = box.longer_side();
  if (size < kMinimumFaceSize) {
    throw InputError("the face has zero or tiny area: its bounding box is " + format_number(box.width(), size * 1e-3) +
                     " x " + format_number(box.height(), size * 1e-3) + ", below the smallest supported size " +
                     format_number(kMinimumFaceSize));
  }
  const double tol = tolerance_for_size(size);
  if (box.shorter_side() <= tol) {
    throw InputError("the face has zero or tiny area: its bounding box is " + format_number(box.width(), tol * 1e-3) +
                     " x " + format_number(box.height(), tol * 1e-3) + " (tolerance " + format_number(tol, tol * 1e-3) + ")");
  }
  return tol;
}

RectilinearPolygon validate_rings(const std::vector<RawRing>& raw, double* tolerance_out) {
  const double tol = face_tolerance(raw);

  // Every edge must run along X or Y, and be longer than the tolerance.
  std::vector<double> xs, ys;
  for (const RawRing& ring : raw) {
    const size_t n = ring.points.size();
    for (size_t k = 0; k < n; ++k) {
      const Point2& a = ring.points[k];
      const Point2& b = ring.points[(k + 1) % n];
      const double dx = std::fabs(b.x - a.x), dy = std::fabs(b.y - a.y);
      const std::string where = "edge " + std::to_string(k + 1) + " of the " + ring.name + ", " + edge_text(a, b, tol);
      if (dx > tol && dy > tol) throw InputError(where + ", is not parallel to the X or Y axis");
      if (dx <= tol && dy <= tol) {
        throw InputError(where + ", is shorter than the tolerance " + format_number(tol, tol * 1e-3));
      }
      xs.push_back(a.x);
      ys.push_back(a.y);
    }
  }
  const std::map<double, double> snap_x = snap_map(xs, tol), snap_y = snap_map(ys, tol);

  std::vector<Ring> rings;
  std::vector<std::string> names;
  for (const RawRing& ring : raw) {
    Ring snapped;
    for (const Point2& p : ring.points) {
      const Point2 q{snap_x.at(p.x), snap_y.at(p.y)};
      if (!snapped.empty() && snapped.back() == q) {
        throw InputError("the " + ring.name + " has vertices too close to tell apart near " + format_point(p.x, p.y, tol) +
                         " (tolerance " + format_number(tol, tol * 1e-3) + ")");
      }
      snapped.push_back(q);
    }
    rings.push_back(merge_collinear(snapped, ring.name, tol));
    names.push_back(ring.name);
  }
  check_no_contact(rings, names, tol);

  // The outer ring is the one with the largest area; every other ring must lie inside it and
  // outside every other hole (rings do not meet, so one vertex decides).
  size_t outer = 0;
  for (size_t r = 1; r < rings.size(); ++r) {
    if (std::fabs(signed_area(rings[r])) > std::fabs(signed_area(rings[outer]))) outer = r;
  }
  RectilinearPolygon polygon;
  for (size_t r = 0; r < rings.size(); ++r) {
    if (r == outer) continue;
    if (!point_in_ring(rings[r][0], rings[outer])) {
      throw InputError("the " + names[r] + " lies outside the " + names[outer] + " (vertex " +
                       format_point(rings[r][0].x, rings[r][0].y, tol) + ")");
    }
    for (size_t s = 0; s < rings.size(); ++s) {
      if (s != outer && s != r && point_in_ring(rings[r][0], rings[s])) {
        throw InputError("the " + names[r] + " lies inside the hole bounded by the " + names[s] +
                         " (vertex " + format_point(rings[r][0].x, rings[r][0].y, tol) + ")");
      }
    }
  }
  for (size_t r = 0; r < rings.size(); ++r) {
    Ring ring = rings[r];
    const bool ccw = signed_area(ring) > 0;
    if (ccw != (r == outer)) std::reverse(ring.begin(), ring.end());
    if (r == outer) {
      polygon.outer = ring;
    } else {
      polygon.holes.push_back(ring);
    }
  }
  if (tolerance_out) *tolerance_out = tol;
  return polygon;
}

}  // namespace autoblock
