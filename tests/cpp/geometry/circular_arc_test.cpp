#include "core/geometry/circular_arc.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace autoblock;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST_CASE("an arc is polygonised into chords of at most 15 degrees, every sample on it", "[geometry][arc]") {
  const CircularArc quarter{{1, 2}, 3.0, 0.0, 0.5 * kPi};  // counter-clockwise from (4, 2) to (1, 5)
  CHECK(arc_chord_count(quarter) == 6);
  const std::vector<Point2> points = polygonise_arc(quarter);
  REQUIRE(points.size() == 7);
  CHECK(points.front().x == Approx(4.0));
  CHECK(points.front().y == Approx(2.0));
  CHECK(points.back().x == Approx(1.0).margin(1e-12));
  CHECK(points.back().y == Approx(5.0));
  for (const Point2& p : points) CHECK(std::hypot(p.x - 1, p.y - 2) == Approx(3.0));
  CHECK(quarter.length() == Approx(1.5 * kPi));
  // A full circle: 24 chords; a small arc: at least 2; clockwise arcs run the other way.
  CHECK(arc_chord_count(CircularArc{{0, 0}, 1.0, 0.3, 2 * kPi}) == 24);
  CHECK(arc_chord_count(CircularArc{{0, 0}, 1.0, 0.3, 0.01}) == 2);
  const CircularArc clockwise{{0, 0}, 2.0, 0.5 * kPi, -0.5 * kPi};  // (0, 2) to (2, 0)
  CHECK(clockwise.point_at(0.5).x == Approx(std::sqrt(2.0)));
  CHECK(clockwise.point_at(0.5).y == Approx(std::sqrt(2.0)));
}

TEST_CASE("points and chords on an arc's polygon are found, others are not", "[geometry][arc]") {
  FaceArcs arcs;
  arcs.arcs.push_back(CircularArc{{0, 0}, 10.0, 0.0, 0.5 * kPi});  // the first quadrant
  arcs.tolerance = 1e-6;
  const std::vector<Point2> samples = polygonise_arc(arcs.arcs[0]);
  // Samples, chord middles and points of a chord lie on the polygon; the centre, a point beyond the
  // arc's end and one outside the circle do not.
  CHECK(arcs.arc_of_point(samples[2]) == 0);
  const Point2 middle{0.5 * (samples[2].x + samples[3].x), 0.5 * (samples[2].y + samples[3].y)};
  CHECK(arcs.arc_of_point(middle) == 0);
  CHECK(arcs.arc_of_point(Point2{0, 0}) == -1);
  CHECK(arcs.arc_of_point(Point2{10 * std::cos(-0.1), 10 * std::sin(-0.1)}) == -1);
  CHECK(arcs.arc_of_point(Point2{10.01, 0.0}) == -1);
  // A chord between neighbouring samples, or part of one, is on the arc; the chord from end to end
  // (90 degrees, its middle far inside the circle) is not, nor is a radius.
  CHECK(arcs.arc_of_chord(samples[2], samples[3]) == 0);
  CHECK(arcs.arc_of_chord(samples[2], middle) == 0);
  CHECK(arcs.arc_of_chord(samples.front(), samples.back()) == -1);
  CHECK(arcs.arc_of_chord(Point2{5, 0}, samples.front()) == -1);
  CHECK(project_to_circle(middle, arcs.arcs[0]).x == Approx(10 * std::cos(0.5 * (2 + 3) * kPi / 12)));
}

TEST_CASE("a mesh's boundary edge along an arc may turn by up to three chord steps, not more", "[geometry][arc]") {
  FaceArcs arcs;
  arcs.arcs.push_back(CircularArc{{0, 0}, 10.0, 0.0, 0.5 * kPi});  // the first quadrant: six 15-degree chords
  arcs.tolerance = 1e-6;
  const auto on = [](double degrees) { return Point2{10 * std::cos(degrees * kPi / 180), 10 * std::sin(degrees * kPi / 180)}; };
  // Ends on the arc: 15, 45 (exactly kMeshEdgeArcSteps steps) and 44 degrees apart are edges along it;
  // 50 and 90 degrees (its middle far inside the circle) are not, nor an edge past the arc's end, nor a
  // radius.
  CHECK(arcs.arc_of_mesh_edge(on(10), on(25)) == 0);
  CHECK(arcs.arc_of_mesh_edge(on(30), on(75)) == 0);
  CHECK(arcs.arc_of_mesh_edge(on(75), on(30)) == 0);
  CHECK(arcs.arc_of_mesh_edge(on(1), on(45)) == 0);
  CHECK(arcs.arc_of_mesh_edge(on(20), on(70)) == -1);
  CHECK(arcs.arc_of_mesh_edge(on(0), on(90)) == -1);
  CHECK(arcs.arc_of_mesh_edge(on(-20), on(10)) == -1);
  CHECK(arcs.arc_of_mesh_edge(Point2{5, 0}, on(0)) == -1);
  // The polygon's own chords (what the engines cut) stay what arc_of_chord finds: two steps at most.
  CHECK(arcs.arc_of_chord(on(30), on(75)) == -1);
  // A full circle (the face outside it: a hole) keeps its chords' rule: one chord step, or two.
  FaceArcs hole;
  hole.arcs.push_back(CircularArc{{0, 0}, 10.0, 0.0, -2 * kPi, true});
  hole.tolerance = 1e-6;
  CHECK(hole.arc_of_mesh_edge(on(-5), on(10)) == 0);
  CHECK(hole.arc_of_mesh_edge(on(-20), on(25)) == -1);
  CHECK(hole.arc_of_mesh_edge(on(-5), on(10)) == hole.arc_of_chord(on(-5), on(10)));
}

TEST_CASE("near a lens's acute tip, an edge along one arc is that arc's, not the other's", "[geometry][arc]") {
  // A lens: two arcs of radius 10 through (0, 0) and (2 r sin 12, 0), each at 12 degrees to the chord
  // there (24-degree tips). Near a tip, points on the lower arc lie in the upper arc's polygon band
  // (two 12-degree chords, a band 10 (1 - cos 6) = 0.055 deep): the edge is still the lower arc's.
  const double half = 12 * kPi / 180, r = 10.0, c = r * std::cos(half);
  const Point2 tip{0, 0};
  FaceArcs arcs;
  // The upper arc (centre below the chord) from the far tip back to (0, 0); the lower one onwards.
  arcs.arcs.push_back(CircularArc{{r * std::sin(half), -c}, r, 0.5 * kPi - half, 2 * half});
  arcs.arcs.push_back(CircularArc{{r * std::sin(half), c}, r, 1.5 * kPi - half, 2 * half});
  arcs.tolerance = 1e-6;
  REQUIRE(std::hypot(arcs.arcs[0].last().x - tip.x, arcs.arcs[0].last().y - tip.y) < 1e-9);
  REQUIRE(std::hypot(arcs.arcs[1].first().x - tip.x, arcs.arcs[1].first().y - tip.y) < 1e-9);
  const CircularArc& lower = arcs.arcs[1];
  const auto on_lower = [&](double degrees) {
    const double a = lower.start + degrees * kPi / 180;
    return Point2{lower.center.x + r * std::cos(a), lower.center.y + r * std::sin(a)};
  };
  // 0.5 degrees along: 0.087 from the tip, 0.036 inside the upper circle, in its band.
  const Point2 near = on_lower(0.5);
  CHECK(arcs.arc_of_point(near) == 0);  // the band holds it
  CHECK(arcs.arc_of_mesh_edge(tip, near) == 1);
  CHECK(arcs.arc_of_mesh_edge(near, on_lower(1.0)) == 1);
  CHECK(arcs.arc_of_mesh_edge(on_lower(5.0), on_lower(10.0)) == 1);
}

TEST_CASE("the gap between a segment and its arc against hand values", "[geometry][arc]") {
  const CircularArc circle2{{0, 0}, 2.0, 0.0, 2 * kPi}, circle3{{0, 0}, 3.0, 0.0, 2 * kPi};
  // A diameter cuts off a half disk; a chord of 90 degrees r^2 (pi / 4 - 1 / 2), positive with the
  // centre on the segment's left (the region there has the segment beyond it), negative run the
  // other way; a zero-length chord nothing.
  CHECK(std::fabs(arc_gap(circle2, {2, 0}, {-2, 0}).area) == Approx(0.5 * kPi * 4.0));
  CHECK(arc_gap(circle3, {3, 0}, {0, 3}).area == Approx(9.0 * (kPi / 4 - 0.5)));
  CHECK(arc_gap(circle3, {0, 3}, {3, 0}).area == Approx(-9.0 * (kPi / 4 - 0.5)));
  CHECK(arc_gap(circle3, {0, 3}, {3, 0}).arc_length == Approx(1.5 * kPi));
  CHECK(arc_gap(circle3, {3, 0}, {3, 0}).area == Approx(0.0).margin(1e-15));
  // A tangent (a circumscribed polygon's side) from -15 to +15 degrees: the region inside the circle
  // lacks the sliver between the tangent and the arc, 9 (pi / 12 - tan 15 degrees).
  const double t = std::tan(kPi / 12);
  CHECK(arc_gap(circle3, {3, -3 * t}, {3, 3 * t}).area == Approx(9.0 * (kPi / 12 - t)));
  CHECK(arc_gap(circle3, {3, -3 * t}, {3, 3 * t}).arc_length == Approx(3.0 * kPi / 6));
}

TEST_CASE("a short arc is one chord: a convex one up to 170 degrees, a concave one up to 120", "[geometry][arc]") {
  // Face size 20: the default element size is 1; these arcs are under 1 long (radius 0.3).
  CircularArc fillet{{0, 0}, 0.3, 0.0, 0.5 * kPi};
  CHECK(short_arc(fillet, 20.0));
  CHECK_FALSE(short_arc(fillet, 5.0));  // an element of 0.25: longer than one
  CircularArc tip{{0, 0}, 0.3, 0.0, 150 * kPi / 180};  // an acute corner's: a flat end of two corners
  CHECK(short_arc(tip, 20.0));
  tip.outside = true;  // concave: its tangents meet 0.3 / cos 75 out, too far for its sharp corner
  CHECK_FALSE(short_arc(tip, 20.0));
  fillet.outside = true;
  CHECK(short_arc(fillet, 20.0));
  CHECK_FALSE(short_arc(CircularArc{{0, 0}, 0.1, 0.0, 2 * kPi}, 20.0));  // a small hole stays a circle
  // Nor is a small lobe of half a circle or more one chord (the chord would cut its neck).
  CHECK_FALSE(short_arc(CircularArc{{0, 0}, 0.1, 0.0, 1.5 * kPi}, 20.0));
  // One chord: inscribed, its two ends; circumscribed, the tangents' meeting point between them (a
  // quarter of its overshoot farther out, so that the ends stay vertices).
  fillet.chords = 1;
  CHECK(arc_chord_count(fillet) == 1);
  const std::vector<Point2> corner = polygonise_arc(fillet);
  REQUIRE(corner.size() == 3);
  const double reach = 0.3 / std::cos(0.25 * kPi);
  CHECK(std::hypot(corner[1].x, corner[1].y) == Approx(reach + 0.25 * (reach - 0.3)));
  fillet.outside = false;
  CHECK(polygonise_arc(fillet).size() == 2);
  // The chord between its ends is a chord of it (its whole sweep, more than two default chord steps).
  FaceArcs arcs;
  arcs.arcs = {fillet};
  arcs.tolerance = 1e-9;
  CHECK(arcs.arc_of_chord(fillet.first(), fillet.last()) == 0);
}

TEST_CASE("a chord at the join of two arcs is the arc's whose polygon it is", "[geometry][arc]") {
  // Where a long convex arc (radius 63.5) begins at the end of a short concave one (radius 7.3, 7.8
  // degrees: one chord, circumscribed: its polygon's corner lies off its circle), the short arc's
  // second chord lies in the long arc's polygon band too (as on a real part's face). It is the short
  // arc's: taken for the long one, the mesh put the corner's node on the wrong circle and lost the
  // join's node.
  CircularArc tip{{-33.8667, -45.0775}, 7.3323, 0.0, -0.1368};
  tip.outside = true;
  tip.chords = 1;
  const Point2 join = tip.last();
  const Point2 centre{-63.2354, 5.7907};
  FaceArcs arcs;
  arcs.arcs.push_back(CircularArc{centre, std::hypot(join.x - centre.x, join.y - centre.y),
                                  std::atan2(join.y - centre.y, join.x - centre.x), 0.8646});
  arcs.arcs.push_back(tip);
  arcs.tolerance = 3e-5;
  const std::vector<Point2> polygon = polygonise_arc(tip);
  REQUIRE(polygon.size() == 3);
  CHECK(std::hypot(join.x - arcs.arcs[0].first().x, join.y - arcs.arcs[0].first().y) < 1e-9);
  CHECK(arcs.arc_of_chord(polygon[0], polygon[1]) == 1);
  CHECK(arcs.arc_of_chord(polygon[1], polygon[2]) == 1);
  // A chord of the long arc is still its own.
  const std::vector<Point2> long_polygon = polygonise_arc(arcs.arcs[0]);
  CHECK(arcs.arc_of_chord(long_polygon[0], long_polygon[1]) == 0);
}

TEST_CASE("a mesh edge square to a convex arc at its end is not on the arc", "[geometry][arc]") {
  // A half annulus's outer arc (radius 46) ends at (46, -0.1), where a straight end runs inwards: a
  // mesh edge along that end, 0.33 long, has both ends in the arc's polygon band and within its
  // directions, but it turns by nothing about the centre: a straight edge, not a chord of the arc
  // (counted as one, the mesh's boundary came out 0.67 short of the face's).
  FaceArcs arcs;
  arcs.arcs.push_back(CircularArc{{0, 0}, 46.0, -3.1394, 3.1372});
  arcs.tolerance = 2e-5;
  const Point2 end = arcs.arcs[0].last();
  CHECK(arcs.arc_of_mesh_edge(Point2{45.6662, end.y}, end) == -1);
  // An edge along the arc from the same end is on it.
  CHECK(arcs.arc_of_mesh_edge(arcs.arcs[0].point_at(0.99), end) == 0);
}
