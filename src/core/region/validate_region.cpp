#include "core/region/validate_region.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "core/common/error.h"
#include "core/common/format.h"

namespace autoblock {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

std::string point_text(Point2 p, double tol) { return format_point(p.x, p.y, tol); }

struct Edge {
  int ring = 0;
  size_t index = 0;
  Point2 a, b;
  double xmin() const { return std::min(a.x, b.x); }
  double xmax() const { return std::max(a.x, b.x); }
};

// The angle between the corner's two edges, in degrees, [0, 180].
double corner_degrees(Point2 p, Point2 v, Point2 n) {
  const double ax = p.x - v.x, ay = p.y - v.y, bx = n.x - v.x, by = n.y - v.y;
  return std::fabs(std::atan2(ax * by - ay * bx, ax * bx + ay * by)) * 180.0 / M_PI;
}

}  // namespace

Region validate_general_rings(const std::vector<RawRing>& raw, double* tolerance_out) {
  const double tol = face_tolerance(raw);
  std::vector<Ring> rings;
  std::vector<std::string> names;
  for (const RawRing& ring : raw) {
    const size_t n = ring.points.size();
    for (size_t k = 0; k < n; ++k) {
      const Point2 a = ring.points[k], b = ring.points[(k + 1) % n];
      if (std::hypot(b.x - a.x, b.y - a.y) <= tol) {
        throw InputError("edge " + std::to_string(k + 1) + " of the " + ring.name + ", from " + point_text(a, tol) + " to " +
                         point_text(b, tol) + ", is shorter than the tolerance " + format_number(tol, tol * 1e-3));
      }
    }
    for (size_t k = 0; k < n; ++k) {
      const Point2 p = ring.points[(k + n - 1) % n], v = ring.points[k], q = ring.points[(k + 1) % n];
      const double degrees = corner_degrees(p, v, q);
      if (degrees < kMinimumCornerDegrees) {
        throw InputError("the " + ring.name + " has a corner of " + format_number(degrees, 0.01) + " degrees at " +
                         point_text(v, tol) + ", sharper than the smallest supported " +
                         format_number(kMinimumCornerDegrees) + " degrees");
      }
    }
    rings.push_back(ring.points);
    names.push_back(ring.name);
  }

  // Edges that are not neighbours must keep more than the tolerance apart (no crossing, no contact, no
  // sliver). Only edges whose x-ranges overlap (widened by the tolerance) can come that close.
  std::vector<Edge> edges;
  for (size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = rings[r];
    for (size_t k = 0; k < ring.size(); ++k) edges.push_back({static_cast<int>(r), k, ring[k], ring[(k + 1) % ring.size()]});
  }
  std::stable_sort(edges.begin(), edges.end(), [](const Edge& s, const Edge& t) { return s.xmin() < t.xmin(); });
  for (size_t i = 0; i < edges.size(); ++i) {
    const Edge& s = edges[i];
    for (size_t j = i + 1; j < edges.size() && edges[j].xmin() <= s.xmax() + tol; ++j) {
      const Edge& t = edges[j];
      if (s.ring == t.ring) {
        const size_t n = rings[static_cast<size_t>(s.ring)].size();
        if ((s.index + 1) % n == t.index || (t.index + 1) % n == s.index) continue;  // neighbours meet at their corner
      }
      const K::Segment_2 u(K::Point_2(s.a.x, s.a.y), K::Point_2(s.b.x, s.b.y));
      const K::Segment_2 w(K::Point_2(t.a.x, t.a.y), K::Point_2(t.b.x, t.b.y));
      const bool cross = CGAL::do_intersect(u, w);
      if (!cross && CGAL::squared_distance(u, w) > tol * tol) continue;
      const Edge& first = s.ring < t.ring || (s.ring == t.ring && s.index < t.index) ? s : t;
      const Edge& second = &first == &s ? t : s;
      const std::string what = cross ? "crosses or touches" : "comes within the tolerance of";
      const std::string subject = s.ring == t.ring ? "the " + names[static_cast<size_t>(s.ring)] + " " + what + " itself"
                                                   : "the " + names[static_cast<size_t>(first.ring)] + " " + what + " the " +
                                                         names[static_cast<size_t>(second.ring)];
      throw InputError(subject + " (edge " + std::to_string(first.index + 1) + " from " + point_text(first.a, tol) + " to " +
                       point_text(first.b, tol) + " and edge " + std::to_string(second.index + 1) + " from " +
                       point_text(second.a, tol) + " to " + point_text(second.b, tol) + ")");
    }
  }

  size_t outer = 0;
  for (size_t r = 1; r < rings.size(); ++r) {
    if (std::fabs(signed_area(rings[r])) > std::fabs(signed_area(rings[outer]))) outer = r;
  }
  std::vector<Ring> holes;
  for (size_t r = 0; r < rings.size(); ++r) {
    if (r == outer) continue;
    if (!point_in_ring(rings[r][0], rings[outer])) {
      throw InputError("the " + names[r] + " lies outside the " + names[outer] + " (vertex " + point_text(rings[r][0], tol) + ")");
    }
    for (size_t s = 0; s < rings.size(); ++s) {
      if (s != outer && s != r && point_in_ring(rings[r][0], rings[s])) {
        throw InputError("the " + names[r] + " lies inside the hole bounded by the " + names[s] + " (vertex " +
                         point_text(rings[r][0], tol) + ")");
      }
    }
    holes.push_back(rings[r]);
  }
  Region region(rings[outer], holes, tol);
  if (region.is_empty() || static_cast<int>(region.holes().size()) != static_cast<int>(holes.size())) {
    throw InputError("the face has zero or tiny area");
  }
  if (tolerance_out) *tolerance_out = tol;
  return region;
}

}  // namespace autoblock
