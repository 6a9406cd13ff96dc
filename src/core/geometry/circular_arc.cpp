#include "core/geometry/circular_arc.h"

#include <algorithm>
#include <cmath>

namespace autoblock {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kEndOvershoot = 0.25;  // see polygonise_arc

// The angle a, taken into [0, 2 pi).
double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}

// Inputs: angle a; arc. Output: how far along the arc's sweep a lies, in radians from its start in the
//         sweep's direction, in [0, 2 pi).
double along(double a, const CircularArc& arc) {
  return arc.sweep >= 0.0 ? wrap(a - arc.start) : wrap(arc.start - a);
}

bool full_circle(const CircularArc& arc) { return std::fabs(arc.sweep) >= kTwoPi - 1e-12; }

}  // namespace

Point2 CircularArc::point_at(double t) const {
  const double a = start + t * sweep;
  return Point2{center.x + radius * std::cos(a), center.y + radius * std::sin(a)};
}

double CircularArc::length() const { return radius * std::fabs(sweep); }

int arc_chord_count(const CircularArc& arc, double max_step_degrees) {
  if (arc.chords > 0) return arc.chords;
  const bool full = full_circle(arc);
  const int count = static_cast<int>(std::ceil(std::fabs(arc.sweep) / (max_step_degrees * kPi / 180.0) - 1e-9));
  return std::max(count, full ? 3 : 2);
}

bool short_arc(const CircularArc& arc, double face_size) {
  const double limit = arc.outside ? kShortArcMaxDegrees : kShortConvexArcMaxDegrees;
  return std::fabs(arc.sweep) <= limit * kPi / 180.0 && arc.length() < kShortArcFraction * face_size;
}

std::vector<Point2> polygonise_arc(const CircularArc& arc, double max_step_degrees) {
  const int n = arc_chord_count(arc, max_step_degrees);
  std::vector<Point2> points;
  points.reserve(static_cast<size_t>(n) + 2);
  if (!arc.outside) {
    for (int k = 0; k <= n; ++k) points.push_back(k == n ? arc.last() : arc.point_at(static_cast<double>(k) / n));
    return points;
  }
  // The tangents' meeting points; at an arc's ends (not a full circle's), a quarter of their overshoot
  // farther out, so that the arc's end is no straight vertex between a tangent neighbour and the first
  // segment (the region's canonical form would merge it, region.h).
  const bool full = full_circle(arc);
  const double reach = arc.radius / std::cos(0.5 * std::fabs(arc.sweep) / n);
  points.push_back(arc.first());
  for (int k = 0; k < n; ++k) {
    const double a = arc.start + arc.sweep * (k + 0.5) / n;
    const double r = !full && (k == 0 || k == n - 1) ? reach + kEndOvershoot * (reach - arc.radius) : reach;
    points.push_back(Point2{arc.center.x + r * std::cos(a), arc.center.y + r * std::sin(a)});
  }
  points.push_back(arc.last());
  return points;
}

bool point_on_arc_polygon(Point2 p, const CircularArc& arc, double tolerance) {
  const double dx = p.x - arc.center.x, dy = p.y - arc.center.y;
  const double d = std::hypot(dx, dy);
  const double half_chord_turn = 0.5 * std::fabs(arc.sweep) / arc_chord_count(arc);
  // Either polygon, and chords between points on the arc (a mesh's boundary edges along it).
  const double inner = arc.radius * std::cos(half_chord_turn);
  const double outer =
      arc.outside ? arc.radius + (1.0 + kEndOvershoot) * (arc.radius / std::cos(half_chord_turn) - arc.radius) : arc.radius;
  if (d > outer + tolerance || d < inner - tolerance) return false;
  if (full_circle(arc)) return true;
  const double slack = tolerance / arc.radius;
  const double s = along(std::atan2(dy, dx), arc);
  return s <= std::fabs(arc.sweep) + slack || s >= kTwoPi - slack;
}

Point2 project_to_circle(Point2 p, const CircularArc& arc) {
  const double dx = p.x - arc.center.x, dy = p.y - arc.center.y;
  const double d = std::hypot(dx, dy);
  if (!(d > 0.0)) return p;
  return Point2{arc.center.x + dx * arc.radius / d, arc.center.y + dy * arc.radius / d};
}

ArcGap arc_gap(const CircularArc& arc, Point2 a, Point2 b) {
  const double ax = a.x - arc.center.x, ay = a.y - arc.center.y, bx = b.x - arc.center.x, by = b.y - arc.center.y;
  const double cross = ax * by - ay * bx;
  const double turn = std::atan2(cross, ax * bx + ay * by);  // signed, (-pi, pi]
  return ArcGap{arc.radius * std::fabs(turn), 0.5 * arc.radius * arc.radius * turn - 0.5 * cross};
}

int FaceArcs::arc_of_point(Point2 p) const {
  for (size_t k = 0; k < arcs.size(); ++k) {
    if (point_on_arc_polygon(p, arcs[k], tolerance)) return static_cast<int>(k);
  }
  return -1;
}

int CircularArc::end_at(Point2 p, double tolerance) const {
  const double near = std::max(1e-9 * radius, tolerance);
  const Point2 a = first(), b = last();
  if (std::hypot(p.x - a.x, p.y - a.y) <= near) return 0;
  if (std::hypot(p.x - b.x, p.y - b.y) <= near) return 1;
  return -1;
}

bool FaceArcs::at_arc_end(Point2 p) const {
  return std::any_of(arcs.begin(), arcs.end(), [&](const CircularArc& arc) { return arc.end_at(p, tolerance) >= 0; });
}

namespace {

// The angle between a and b as seen from the arc's centre, in [0, pi].
double turn_between(const CircularArc& arc, Point2 a, Point2 b) {
  const double ta = std::atan2(a.y - arc.center.y, a.x - arc.center.x);
  const double tb = std::atan2(b.y - arc.center.y, b.x - arc.center.x);
  const double turn = std::fabs(ta - tb);
  return turn > kPi ? kTwoPi - turn : turn;
}

// a -> b runs across the circle's radii, not along them: its ends' distances from the centre differ by
// more than half its turn's length. A mesh's straight boundary edge meeting a convex arc's end square
// to it lies in the band of the arc's polygon, both its ends "on" the arc, a chord of no turn; a mesh
// edge along the arc has both ends on the circle. (Not for polygon chords: a circumscribed polygon's
// corner lies off the circle.)
bool radial(const CircularArc& arc, Point2 a, Point2 b, double tolerance) {
  const double da = std::hypot(a.x - arc.center.x, a.y - arc.center.y), db = std::hypot(b.x - arc.center.x, b.y - arc.center.y);
  return std::fabs(da - db) > tolerance + 0.5 * arc.radius * turn_between(arc, a, b);
}

// Both ends and the middle of a -> b on the arc's polygon, the ends at most two chord steps apart (the
// default's, or a short arc's one chord: the whole arc) as seen from the centre.
bool chord_on_arc(const CircularArc& arc, Point2 a, Point2 b, double tolerance) {
  const Point2 m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  const double max_turn = std::max(2.0 * kArcStepDegrees * kPi / 180.0, 2.0 * std::fabs(arc.sweep) / arc_chord_count(arc));
  if (!point_on_arc_polygon(a, arc, tolerance) || !point_on_arc_polygon(b, arc, tolerance) ||
      !point_on_arc_polygon(m, arc, tolerance)) {
    return false;
  }
  // Within the arc's directions: a chord of the next arc along its tangent (a short concave arc's
  // corner, where a long arc begins) is not a chord of this one.
  if (!full_circle(arc)) {
    const double slack = tolerance / arc.radius;
    const double s = along(std::atan2(m.y - arc.center.y, m.x - arc.center.x), arc);
    if (!(s <= std::fabs(arc.sweep) + slack || s >= kTwoPi - slack)) return false;
  }
  return turn_between(arc, a, b) <= max_turn;
}

}  // namespace

int FaceArcs::arc_of_mesh_edge(Point2 a, Point2 b) const {
  const Point2 m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  auto on = [&](const CircularArc& arc) {
    if (arc.outside) return chord_on_arc(arc, a, b, tolerance);  // a hole's arc or a concave fillet: its chords only (arc_of_chord)
    const double step = std::fabs(arc.sweep) / arc_chord_count(arc);
    const double max_turn = std::max(kMeshEdgeArcSteps * kArcStepDegrees * kPi / 180.0, 2.0 * step);
    if (!point_on_arc_polygon(a, arc, tolerance) || !point_on_arc_polygon(b, arc, tolerance)) return false;
    const double turn = turn_between(arc, a, b);
    if (turn > max_turn + 1e-9 + tolerance / arc.radius) return false;  // (an edge of exactly max_turn, rounded)
    if (radial(arc, a, b, tolerance)) return false;
    // The middle: no nearer the centre than the chord of that turn (less the arc's own band), not
    // outside the circle, and within the arc's directions.
    const double d = std::hypot(m.x - arc.center.x, m.y - arc.center.y);
    const double inner = arc.radius * std::min(std::cos(0.5 * turn), std::cos(0.5 * step));
    if (d < inner - tolerance || d > arc.radius + tolerance) return false;
    if (!full_circle(arc)) {
      const double slack = tolerance / arc.radius;
      const double s = along(std::atan2(m.y - arc.center.y, m.x - arc.center.x), arc);
      if (!(s <= std::fabs(arc.sweep) + slack || s >= kTwoPi - slack)) return false;
    }
    return true;
  };
  // Where two arcs meet at an acute tip, an edge along one near the tip lies in the other's polygon
  // band too: the arc whose circle both ends lie on is the edge's.
  auto on_circle = [&](const CircularArc& arc, Point2 p) {
    return std::fabs(std::hypot(p.x - arc.center.x, p.y - arc.center.y) - arc.radius) <= tolerance;
  };
  int found = -1;
  for (size_t k = 0; k < arcs.size(); ++k) {
    if (!on(arcs[k])) continue;
    if (on_circle(arcs[k], a) && on_circle(arcs[k], b)) return static_cast<int>(k);
    if (found < 0) found = static_cast<int>(k);
  }
  return found;
}

int FaceArcs::arc_of_chord(Point2 a, Point2 b) const {
  int found = -1;
  for (size_t k = 0; k < arcs.size(); ++k) {
    if (!chord_on_arc(arcs[k], a, b, tolerance)) continue;
    // Where arcs meet, a chord of one can lie in the band of another (a long arc's polygon band is
    // wide: a short arc's chord at its end lies in it): the arc whose polygon has both ends as its
    // vertices is the chord's.
    const std::vector<Point2> polygon = polygonise_arc(arcs[k]);
    auto vertex = [&](Point2 p) {
      return std::any_of(polygon.begin(), polygon.end(), [&](Point2 q) { return std::hypot(p.x - q.x, p.y - q.y) <= tolerance; });
    };
    if (vertex(a) && vertex(b)) return static_cast<int>(k);
    if (found < 0) found = static_cast<int>(k);
  }
  return found;
}

}  // namespace autoblock
