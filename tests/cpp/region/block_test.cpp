#include "core/region/block.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <catch2/catch.hpp>

#include "core/geometry/rectilinear_polygon.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {
constexpr double kQ = 1e-7;

// Every corner of the piece's quadrilateral of corners within [20, 160] degrees.
void check_corner_angles(const QuadPiece& piece) {
  for (int k = 0; k < 4; ++k) {
    const CornerAngle a = piece_corner_angle(piece, k);
    const double degrees = std::atan2(a.sine, a.cosine) * 180.0 / M_PI;
    CHECK(degrees >= 20.0);
    CHECK(degrees <= 160.0);
  }
}

}  // namespace

TEST_CASE("blocks: four corners within the angle range, side vertices allowed", "[region][block]") {
  CHECK(is_block(Region(Ring{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, {}, kQ)));
  // A side vertex at (1.5, 0.05) bends the bottom side by about 4 degrees: still four corners.
  const Region bent(Ring{{0, 0}, {1.5, 0.05}, {3, 0}, {3, 1}, {0, 1}}, {}, kQ);
  const auto corners = block_corners(bent);
  REQUIRE(corners);
  CHECK((*corners)[0] == 0);
  CHECK((*corners)[1] == 2);
  // A parallelogram at 60 degrees is a block; at 20 degrees it is not (default range 30-150).
  CHECK(is_block(Region(Ring{{0, 0}, {4, 0}, {5, std::sqrt(3.0)}, {1, std::sqrt(3.0)}}, {}, kQ)));
  const double t = 20.0 * M_PI / 180.0;
  const Region sharp(Ring{{0, 0}, {4, 0}, {4 + std::cos(t), std::sin(t)}, {std::cos(t), std::sin(t)}}, {}, kQ);
  CHECK_FALSE(is_block(sharp));
  BlockRules loose;
  loose.min_corner_degrees = 15.0;
  loose.max_corner_degrees = 165.0;
  loose.flat_tolerance_degrees = 10.0;
  CHECK(is_block(sharp, loose));
  // Triangles, pentagons, L-shapes and holed squares are not blocks.
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {1, 0}, {0, 1}}, {}, kQ)));
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 1}}, {}, kQ)));
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, kQ)));
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {Ring{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}, kQ)));
}

TEST_CASE("the template: n quadrilaterals that tile the convex part", "[region][block]") {
  const Region triangle(Ring{{0, 0}, {6, 0}, {0, 6}}, {}, kQ);
  REQUIRE(template_applies(triangle));
  const auto quads = template_quads(triangle);
  REQUIRE(quads.size() == 3);
  double area = 0.0;
  for (const auto& q : quads) {
    double a = 0.0;
    for (size_t i = 0; i < 4; ++i) a += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
    CHECK(a > 0.0);  // counter-clockwise, not inverted
    area += 0.5 * a;
  }
  CHECK(area == Approx(18.0));
  // The centre is the incentre (the largest circle touches all three sides), and the spokes meet
  // the sides at right angles: each quad's corners are t, 90, 180 - t, 90 for its triangle corner t.
  const double r = (6.0 + 6.0 - std::sqrt(72.0)) / 2.0;
  CHECK(quads[0][2].x == Approx(r));
  CHECK(quads[0][2].y == Approx(r));
  for (const auto& q : quads) {
    auto angle = [&](size_t i) {
      const Point2 a = q[(i + 3) % 4], b = q[i], c = q[(i + 1) % 4];
      const double u = std::atan2(a.y - b.y, a.x - b.x), v = std::atan2(c.y - b.y, c.x - b.x);
      double t = std::fabs(u - v);
      return t > M_PI ? 2.0 * M_PI - t : t;
    };
    CHECK(angle(1) == Approx(M_PI / 2.0));
    CHECK(angle(3) == Approx(M_PI / 2.0));
    CHECK(angle(0) + angle(2) == Approx(M_PI));
  }
  CHECK_FALSE(template_applies(Region(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, kQ)));
  // One quad per corner; a side vertex adds none.
  CHECK(template_quads(Region(Ring{{0, 0}, {4, 0}, {5, 2}, {2, 5}, {-1, 2}}, {}, kQ)).size() == 5);
  CHECK(template_quads(Region(Ring{{0, 0}, {3, 0}, {6, 0}, {0, 6}}, {}, kQ)).size() == 3);
}

TEST_CASE("the minimum-area rectangle: a turned rectangle is found in its own frame", "[region][block]") {
  const Region axis(Ring{{0, 0}, {4, 0}, {4, 1}, {0, 1}}, {}, kQ);
  const OrientedRectangle r = min_area_rectangle(axis);
  CHECK(r.axis.x == Approx(1.0));
  CHECK(r.aspect_ratio() == Approx(4.0));
  for (double degrees : {10.0, 33.0, 45.0, 71.0, 120.0}) {
    const double t = degrees * M_PI / 180.0, c = std::cos(t), s = std::sin(t);
    Ring turned;
    for (const Point2& p : axis.outer()) turned.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
    const OrientedRectangle m = min_area_rectangle(Region(turned, {}, kQ));
    CHECK(m.aspect_ratio() == Approx(4.0));
    CHECK(m.width * m.height == Approx(4.0));
  }
}

TEST_CASE("template pieces: four-sided loops through side vertices, sharing spokes", "[region][block]") {
  // A pentagon with a side vertex (bent by 3 degrees) on its bottom side, left of that side's midpoint.
  const Region pentagon(Ring{{0, 0}, {1, -0.05}, {4, 0}, {5, 2}, {2, 4}, {-1, 2}}, {}, kQ);
  REQUIRE(template_applies(pentagon));
  const auto pieces = template_pieces(pentagon);
  REQUIRE(pieces.size() == 5);
  double area = 0.0;
  const QuadPiece* from_origin = nullptr;
  for (const QuadPiece& p : pieces) {
    CHECK(p.corners[0] == 0);
    CHECK(p.corners[1] < p.corners[2]);
    CHECK(p.corners[2] < p.corners[3]);
    CHECK(p.ring[static_cast<size_t>(p.corners[2])] == pieces[0].ring[static_cast<size_t>(pieces[0].corners[2])]);
    CHECK(point_in_ring(p.ring[static_cast<size_t>(p.corners[2])], pentagon.outer()));
    double a = 0.0;
    for (size_t i = 0; i < p.ring.size(); ++i) a += p.ring[i].x * p.ring[(i + 1) % p.ring.size()].y - p.ring[(i + 1) % p.ring.size()].x * p.ring[i].y;
    CHECK(a > 0.0);
    area += 0.5 * a;
    if (p.ring[0] == Point2{0, 0}) from_origin = &p;
  }
  CHECK(area == Approx(pentagon.area()));
  // The side vertex lies on the boundary of the piece at (0, 0), before the bottom side's midpoint.
  REQUIRE(from_origin);
  CHECK(from_origin->corners[1] == 2);
  CHECK(from_origin->ring[1].x == Approx(1.0));
  CHECK(from_origin->ring[1].y == Approx(-0.05));
  CHECK(from_origin->ring[2].x == Approx(2.0).margin(0.01));
  // A side vertex at a side's midpoint is the midpoint.
  const Region square(Ring{{0, 0}, {1, -0.01}, {2, 0}, {2, 2}, {0, 2}}, {}, kQ);
  const auto square_pieces = template_pieces(square);
  REQUIRE(square_pieces.size() == 4);
  bool found = false;
  for (const QuadPiece& p : square_pieces) {
    CHECK(p.ring.size() == 4);
    const Point2 mid = p.ring[static_cast<size_t>(p.corners[1])];
    found = found || (std::fabs(mid.x - 1.0) < 1e-6 && std::fabs(mid.y + 0.01) < 1e-6);
  }
  CHECK(found);
}

TEST_CASE("template pieces: a foot a hair from a side vertex is that vertex", "[region][block]") {
  // A triangle whose bottom side has a side vertex (bent by a tenth of a degree) near where the spoke
  // from the centre (x = 5) meets it. 0.02 away, the foot is the vertex: no edge 0.02 long between
  // them, whose quads would be triangles with an edge of no length. 0.6 away (more than a twentieth of
  // the shorter edge beside it), the foot stays where the spoke meets the side.
  for (const double x : {5.02, 4.98, 5.6}) {
    const Region triangle(Ring{{0, 0}, {x, -0.01}, {10, 0}, {5, 8}}, {}, kQ);
    REQUIRE(template_applies(triangle));
    const auto pieces = template_pieces(triangle);
    REQUIRE(pieces.size() == 3);
    const QuadPiece* from_origin = nullptr;
    double shortest = 1e300;
    for (const QuadPiece& p : pieces) {
      if (p.ring[0] == Point2{0, 0}) from_origin = &p;
      for (size_t i = 0; i < p.ring.size(); ++i) {
        const Point2 a = p.ring[i], b = p.ring[(i + 1) % p.ring.size()];
        shortest = std::min(shortest, std::hypot(b.x - a.x, b.y - a.y));
      }
    }
    REQUIRE(from_origin);
    const Point2 foot = from_origin->ring[static_cast<size_t>(from_origin->corners[1])];
    INFO("side vertex at x = " << x);
    if (x == 5.6) {
      CHECK(foot.x == Approx(5.0).margin(0.01));
      CHECK(shortest > 0.5);
    } else {
      CHECK(foot.x == Approx(x).margin(1e-6));
      CHECK(foot.y == Approx(-0.01).margin(1e-6));
      CHECK(shortest > 2.0);  // the spokes, 2.77
    }
  }
}

TEST_CASE("the scaled Jacobian bound of a face's corners", "[region][block]") {
  CHECK(scaled_jacobian_bound({Ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}) == Approx(1.0));
  // An L-shape's reflex corner (270 degrees) takes three right angles.
  CHECK(scaled_jacobian_bound({Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}}) == Approx(1.0));
  // A chamfered square: 135-degree corners, two quads of 67.5 degrees.
  CHECK(scaled_jacobian_bound({Ring{{1, 0}, {3, 0}, {4, 1}, {4, 3}, {3, 4}, {1, 4}, {0, 3}, {0, 1}}}) ==
        Approx(std::sin(67.5 * M_PI / 180.0)));
  // An equilateral triangle: 60 degrees, one quad.
  CHECK(scaled_jacobian_bound({Ring{{0, 0}, {2, 0}, {1, std::sqrt(3.0)}}}) == Approx(std::sin(M_PI / 3.0)));
  // A triangular hole (clockwise) with a 30-degree corner: for the face that corner is reflex, 330
  // degrees, best split into four quads of 82.5 degrees (its 75-degree corners give 285: three of 95).
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const double t = 30.0 * M_PI / 180.0;
  const Ring sharp_hole{{4, 4}, {4 + 3 * std::cos(t), 4 + 3 * std::sin(t)}, {7, 4}};  // clockwise
  CHECK(scaled_jacobian_bound({square, sharp_hole}) == Approx(std::sin(82.5 * M_PI / 180.0)));
}

TEST_CASE("the O-grid template: a box around a round hole, twelve pieces", "[region][block][arc]") {
  // A 10 x 6 plate with a hole of radius 1.5 at (4, 3), its circle as the face reader gives it
  // (circumscribed: the polygon's vertices lie just outside the circle).
  auto round_hole = [](double x, double y, double r) { return test::round_hole({x, y}, r); };
  const Ring plate{{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  const Region part(plate, {round_hole(4, 3, 1.5)}, kQ);
  REQUIRE(template_applies(part));
  REQUIRE(ogrid_template(part));
  const std::vector<QuadPiece> pieces = template_pieces(part);
  REQUIRE(pieces.size() == 12);
  double area = 0.0;
  for (size_t p = 0; p < pieces.size(); ++p) {
    const QuadPiece& piece = pieces[p];
    CHECK(signed_area(piece.ring) > 0.0);
    area += signed_area(piece.ring);
    // The corner and side pieces (the first eight) are rectangles; a ring piece's corners at the box
    // make up the box's right angle between them.
    for (size_t k = 0; k < 4; ++k) {
      const Point2 v = piece.ring[static_cast<size_t>(piece.corners[k])];
      const Point2 next = piece.ring[static_cast<size_t>(piece.corners[(k + 1) % 4])];
      const Point2 prev = piece.ring[static_cast<size_t>(piece.corners[(k + 3) % 4])];
      const double cosine = ((next.x - v.x) * (prev.x - v.x) + (next.y - v.y) * (prev.y - v.y)) /
                            (std::hypot(next.x - v.x, next.y - v.y) * std::hypot(prev.x - v.x, prev.y - v.y));
      if (p < 8) CHECK(std::fabs(cosine) < 1e-6);
    }
  }
  CHECK(area == Approx(part.area()).epsilon(1e-9));
  // Every hole vertex lies on a ring piece: the four ring pieces go round the hole once.
  size_t on_ring_pieces = 0;
  for (size_t p = 8; p < 12; ++p) on_ring_pieces += pieces[p].ring.size() - 3;
  CHECK(on_ring_pieces == part.holes()[0].size());
  // The box's first corner (lower left): halfway between the hole and the sides, at most a radius
  // beyond the hole. The hole's polygon reaches 1.5 from its centre towards each side (its edges are
  // tangents, one of them at each axis direction).
  const Point2 c = ring_centroid(part.holes()[0]);
  double reach_left = 0.0, reach_down = 0.0;
  for (const Point2& v : part.holes()[0]) reach_left = std::max(reach_left, c.x - v.x), reach_down = std::max(reach_down, c.y - v.y);
  CHECK(reach_left == Approx(1.5).margin(1e-6));
  CHECK(reach_down == Approx(1.5).margin(1e-6));
  const Point2 box = pieces[8].ring[0];
  CHECK(box.x == Approx(4.0 - 0.5 * (1.5 + 4.0)).margin(1e-6));  // 2.75 left of the centre: halfway
  CHECK(box.y == Approx(3.0 - 0.5 * (1.5 + 3.0)).margin(1e-6));  // 2.25 below: halfway
  // A small hole: the box a radius beyond it.
  const std::vector<QuadPiece> small = template_pieces(Region(plate, {round_hole(4, 3, 0.5)}, kQ));
  REQUIRE(small.size() == 12);
  CHECK(small[8].ring[0].x == Approx(3.0).margin(1e-6));
  CHECK(small[8].ring[0].y == Approx(2.0).margin(1e-6));

  // Not an O-grid: a hole too near a side, a hole with corners, two holes, a part with six corners.
  CHECK_FALSE(ogrid_template(Region(plate, {round_hole(1.8, 3, 1.5)}, kQ)));
  CHECK_FALSE(ogrid_template(Region(plate, {Ring{{3, 2}, {3, 4}, {5, 4}, {5, 2}}}, kQ)));
  CHECK_FALSE(template_applies(Region(plate, {Ring{{3, 2}, {3, 4}, {5, 4}, {5, 2}}}, kQ)));
  CHECK_FALSE(ogrid_template(Region(plate, {round_hole(2.5, 3, 0.8), round_hole(7.5, 3, 0.8)}, kQ)));
  const Ring l_shape{{0, 0}, {10, 0}, {10, 6}, {6, 6}, {6, 10}, {0, 10}};
  CHECK_FALSE(ogrid_template(Region(l_shape, {round_hole(3, 3, 1)}, kQ)));
}

TEST_CASE("the O-grid template in a tight cell: the part's sides are the box, four pieces", "[region][block][arc]") {
  // A staggered grid's cell: 4 x 3.6 about a hole of radius 1.5, a fifth of a radius from the long
  // sides and a third from the short ones: no room for a box (kOgridClearance), each corner spoked to
  // the hole instead.
  const Region cell(Ring{{0, 0}, {4, 0}, {4, 3.6}, {0, 3.6}}, {test::round_hole({2, 1.8}, 1.5)}, kQ);
  REQUIRE(ogrid_template(cell));
  const std::vector<QuadPiece> pieces = template_pieces(cell);
  REQUIRE(pieces.size() == 4);
  double area = 0.0;
  size_t on_hole = 0;
  const Ring& hole = cell.holes()[0];
  for (size_t p = 0; p < 4; ++p) {
    const QuadPiece& piece = pieces[p];
    CHECK(signed_area(piece.ring) > 0.0);
    area += signed_area(piece.ring);
    // Its first two corners are the cell's corners p and p + 1, the other two on the hole, each about
    // in the direction of its cell corner from the centre; no corner sharper than 40 degrees.
    CHECK(piece.ring[static_cast<size_t>(piece.corners[0])] == cell.outer()[p]);
    CHECK(piece.ring[static_cast<size_t>(piece.corners[1])] == cell.outer()[(p + 1) % 4]);
    for (const int k : {2, 3}) {
      const Point2 v = piece.ring[static_cast<size_t>(piece.corners[static_cast<size_t>(k)])];
      CHECK(std::find(hole.begin(), hole.end(), v) != hole.end());
      const Point2 corner = cell.outer()[(p + (k == 2 ? 1 : 0)) % 4];
      const double off = std::remainder(std::atan2(v.y - 1.8, v.x - 2) - std::atan2(corner.y - 1.8, corner.x - 2), 2 * M_PI);
      CHECK(std::fabs(off) < 8 * M_PI / 180);
    }
    for (int k = 0; k < 4; ++k) CHECK(piece_corner_angle(piece, k).sine > std::sin(40 * M_PI / 180));
    on_hole += piece.ring.size() - 3;
  }
  CHECK(area == Approx(cell.area()).epsilon(1e-9));
  CHECK(on_hole == hole.size());  // the four pieces go round the hole once
  // Not a tight O-grid: a hole a twentieth of a radius from a side; a hole tight on one side and far
  // from another (that part wants a cut, not spokes); a rhombus's 60-degree corners, which spokes
  // would halve.
  CHECK_FALSE(ogrid_template(Region(Ring{{0, 0}, {4, 0}, {4, 3.15}, {0, 3.15}}, {test::round_hole({2, 1.575}, 1.5)}, kQ)));
  CHECK_FALSE(ogrid_template(Region(Ring{{0, 0}, {8, 0}, {8, 3.6}, {0, 3.6}}, {test::round_hole({2, 1.8}, 1.5)}, kQ)));
  const double h = 3.6 / std::sin(M_PI / 3);
  const Ring rhombus{{0, 0}, {h, 0}, {h + 0.5 * h, 3.6}, {0.5 * h, 3.6}};
  CHECK_FALSE(ogrid_template(Region(rhombus, {test::round_hole({0.75 * h, 1.8}, 1.5)}, kQ)));
}

namespace {
// An annular sector about the origin (a flange's cell): radii r1 < r2, from angle -half to half
// (degrees), its arcs sampled every step degrees, counter-clockwise.
Ring annular_sector(double r1, double r2, double half, double step) {
  Ring ring;
  const int n = static_cast<int>(std::lround(2.0 * half / step));
  auto at = [](double r, double degrees) {
    return Point2{r * std::cos(degrees * M_PI / 180.0), r * std::sin(degrees * M_PI / 180.0)};
  };
  for (int i = 0; i <= n; ++i) ring.push_back(at(r2, -half + i * step));  // the rim, anticlockwise
  for (int i = 0; i <= n; ++i) ring.push_back(at(r1, half - i * step));   // the bore, back
  return ring;
}

// Inputs: a template's pieces. Output: their total area, each piece checked counter-clockwise.
double checked_pieces_area(const std::vector<QuadPiece>& pieces) {
  double area = 0.0;
  for (const QuadPiece& piece : pieces) {
    CHECK(signed_area(piece.ring) > 0.0);
    area += signed_area(piece.ring);
  }
  return area;
}
}  // namespace

TEST_CASE("the O-grid template in an annular sector: curved sides, twelve pieces", "[region][block][arc]") {
  // A flange's cell: radii 20 and 40, 36 degrees wide (as long round its middle as it is deep), a
  // bolt hole of radius 3 at its middle. The bore's arc bulges towards the hole, the rim's away.
  const Region part(annular_sector(20, 40, 18, 6), {test::round_hole({30, 0}, 3)}, kQ);
  REQUIRE(ogrid_template(part));
  const std::vector<QuadPiece> pieces = template_pieces(part);
  REQUIRE(pieces.size() == 12);
  // (The feet on the arcs are rounded to the lattice, off their chords by half a quantum.)
  CHECK(checked_pieces_area(pieces) == Approx(part.area()).epsilon(1e-8));
  // The feet on the arcs lie on their polygons: each corner piece's second and fourth corners are on
  // the part's boundary, each within a quantum or two of a chord of the ring.
  auto on_ring = [&](Point2 p) {
    double best = std::numeric_limits<double>::infinity();
    const Ring& ring = part.outer();
    for (size_t i = 0; i < ring.size(); ++i) best = std::min(best, segment_distance(p, ring[i], ring[(i + 1) % ring.size()]));
    return best;
  };
  for (size_t p = 0; p < 4; ++p) {
    CHECK(on_ring(pieces[p].ring[static_cast<size_t>(pieces[p].corners[1])]) < 3 * kQ);
    CHECK(on_ring(pieces[p].ring[static_cast<size_t>(pieces[p].corners[3])]) < 3 * kQ);
  }
  // The box keeps clear of the bore's bulge: every box corner is farther from the origin than the
  // bore's radius and nearer than the rim's.
  for (size_t p = 8; p < 12; ++p) {
    const Point2 box = pieces[p].ring[0];
    CHECK(std::hypot(box.x, box.y) > 20.0);
    CHECK(std::hypot(box.x, box.y) < 40.0);
  }
  // A deep, narrow sector (a flange of 24 bolt holes: 15 degrees, 40 deep): the radial sides
  // converge so fast that the feet square to the bore's side fall outside it; the feet along the box
  // lines are taken, and the strips beside the box keep their width.
  const Region narrow(annular_sector(20, 60, 7.5, 2.5), {test::round_hole({40, 0}, 2.5)}, kQ);
  REQUIRE(ogrid_template(narrow));
  const std::vector<QuadPiece> strips = template_pieces(narrow);
  REQUIRE(strips.size() == 12);
  CHECK(checked_pieces_area(strips) == Approx(narrow.area()).epsilon(1e-8));
  // A quarter ring bends its sides by 90 degrees: too much for the box's straight sides.
  CHECK_FALSE(ogrid_template(Region(annular_sector(20, 40, 45, 15), {test::round_hole({30, 0}, 3)}, kQ)));
  // One curved side (a cell that a chord between two bolt circles cut off from the rim, or a plate's
  // cell under a rounded edge): an arc of radius 13 about (5, -6) from (10, 6) to (0, 6), turning 45
  // degrees, over a straight side. The feet on it lie on its polygon.
  Ring arched{{0, 0}, {10, 0}, {10, 6}};
  const double from = std::atan2(12.0, 5.0), to = std::atan2(12.0, -5.0);
  for (int i = 1; i < 6; ++i) {
    const double t = from + i * (to - from) / 6.0;
    arched.push_back({5 + 13 * std::cos(t), -6 + 13 * std::sin(t)});
  }
  arched.push_back({0, 6});
  const Region cell(arched, {test::round_hole({5, 3.5}, 1)}, kQ);
  REQUIRE(ogrid_template(cell));
  const std::vector<QuadPiece> under_arc = template_pieces(cell);
  REQUIRE(under_arc.size() == 12);
  CHECK(checked_pieces_area(under_arc) == Approx(cell.area()).epsilon(1e-8));
  for (size_t p = 0; p < 4; ++p) {
    for (const int corner : {1, 3}) {
      const Point2 foot = under_arc[p].ring[static_cast<size_t>(under_arc[p].corners[static_cast<size_t>(corner)])];
      double best = std::numeric_limits<double>::infinity();
      for (size_t i = 0; i < arched.size(); ++i) best = std::min(best, segment_distance(foot, arched[i], arched[(i + 1) % arched.size()]));
      CHECK(best < 3 * kQ);
    }
  }
  // A hole near the bore: no room.
  CHECK_FALSE(ogrid_template(Region(annular_sector(20, 40, 18, 6), {test::round_hole({23.5, 0}, 3)}, kQ)));
}

TEST_CASE("the topology bound: corners and the irregular vertices a face's holes and smooth loops need",
          "[region][block][arc]") {
  const double sin72 = std::sin(0.4 * M_PI), sin120 = std::sin(2.0 * M_PI / 3.0);
  auto circle = [](double x, double y, double r, bool hole) {
    CircularArc arc;
    arc.center = {x, y};
    arc.radius = r;
    arc.sweep = hole ? -2.0 * M_PI : 2.0 * M_PI;
    arc.outside = hole;
    return arc;
  };
  auto polygon = [](const CircularArc& arc) {
    Ring ring = polygonise_arc(arc);
    ring.pop_back();  // a full circle ends where it starts
    return ring;
  };
  const Ring plate{{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  // Polygons whose corners settle it: a rectangle, an L (its reflex corner three quads), a triangle
  // (one quad a corner: a three-valent vertex inside, as its corners' sin 60), a chamfered square.
  CHECK(topology_jacobian_bound({plate}, {}) == Approx(1.0));
  CHECK(topology_jacobian_bound({Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}}, {}) == Approx(1.0));
  CHECK(topology_jacobian_bound({Ring{{0, 0}, {2, 0}, {1, std::sqrt(3.0)}}}, {}) == Approx(std::sin(M_PI / 3.0)));
  // A chamfered square: its eight 135-degree corners split in two (sin 67.5 = 0.924) leave 4 over,
  // four three-valent vertices; one quad at four of them (sin 135 = 0.707) would settle the sum.
  const Ring chamfered{{1, 0}, {3, 0}, {4, 1}, {4, 3}, {3, 4}, {1, 4}, {0, 3}, {0, 1}};
  CHECK(scaled_jacobian_bound({chamfered}) == Approx(std::sin(67.5 * M_PI / 180.0)));
  CHECK(topology_jacobian_bound({chamfered}, {}) == Approx(sin120));
  // A regular pentagon: 108-degree corners, one quad each, one five-valent vertex inside (sin 72 both).
  Ring pentagon;
  for (int k = 0; k < 5; ++k) pentagon.push_back({std::cos(0.4 * M_PI * k), std::sin(0.4 * M_PI * k)});
  CHECK(topology_jacobian_bound({pentagon}, {}) == Approx(sin72));
  // A rectangular hole: its four reflex corners make up the plate's four convex ones.
  CHECK(topology_jacobian_bound({plate, Ring{{4, 2}, {4, 4}, {6, 4}, {6, 2}}}, {}) == Approx(1.0));
  // A round hole has no corner to do so: five-valent vertices inside (the corner bound says 1).
  FaceArcs hole_arcs;
  hole_arcs.arcs = {circle(5, 3, 1.5, true)};
  hole_arcs.tolerance = 1e-6;
  const std::vector<Ring> plate_with_hole{plate, polygon(hole_arcs.arcs[0])};
  CHECK(scaled_jacobian_bound(plate_with_hole, hole_arcs) == Approx(1.0));
  CHECK(topology_jacobian_bound(plate_with_hole, hole_arcs) == Approx(sin72));
  // A disk: no corner at all, four three-valent vertices.
  FaceArcs disk_arcs;
  disk_arcs.arcs = {circle(0, 0, 2, false)};
  disk_arcs.tolerance = 1e-6;
  CHECK(boundary_corner_angles({polygon(disk_arcs.arcs[0])}, disk_arcs).empty());
  CHECK(topology_jacobian_bound({polygon(disk_arcs.arcs[0])}, disk_arcs) == Approx(sin120));
  // An annulus: the two circles need nothing (a polar grid).
  FaceArcs annulus_arcs;
  annulus_arcs.arcs = {circle(0, 0, 3, false), circle(0, 0, 1, true)};
  annulus_arcs.tolerance = 1e-6;
  CHECK(topology_jacobian_bound({polygon(annulus_arcs.arcs[0]), polygon(annulus_arcs.arcs[1])}, annulus_arcs) ==
        Approx(1.0));
}

TEST_CASE("smooth parts: the disk's template, and no template on a part with a concave arc", "[region][block][arc]") {
  // A 24-gon (a polygonised circle): no corners, so the disk's template: four spokes to an inner
  // quadrilateral halfway to the centre, five pieces tiling the part, each convex.
  Ring circle;
  for (int k = 0; k < 24; ++k) circle.push_back({5 + 3 * std::cos(k * M_PI / 12 + 0.1), 2 + 3 * std::sin(k * M_PI / 12 + 0.1)});
  const Region disk(circle, {}, kQ);
  REQUIRE(template_applies(disk));
  REQUIRE(smooth_template(disk));
  const std::vector<QuadPiece> pieces = template_pieces(disk);
  REQUIRE(pieces.size() == 5);
  double area = 0;
  for (const QuadPiece& piece : pieces) {
    area += signed_area(piece.ring);
    for (size_t k = 0; k < 4; ++k) {
      const Point2 v = piece.ring[static_cast<size_t>(piece.corners[k])];
      const Point2 next = piece.ring[static_cast<size_t>(piece.corners[(k + 1) % 4])];
      const Point2 prev = piece.ring[static_cast<size_t>(piece.corners[(k + 3) % 4])];
      CHECK((next.x - v.x) * (prev.y - v.y) - (next.y - v.y) * (prev.x - v.x) > 0);
    }
  }
  CHECK(area == Approx(disk.area()).epsilon(1e-9));
  // The inner quadrilateral's corners lie halfway between the centre and the boundary.
  for (const Point2& p : pieces.back().ring) CHECK(std::hypot(p.x - 5, p.y - 2) == Approx(1.5).epsilon(1e-6));
}

TEST_CASE("a part with two corners: the two-corner template keeps them whole, two three-valent vertices inside",
          "[region][block][arc]") {
  // A circular segment: a chord 10 long under an arc of 120 degrees in 10-degree samples (radius
  // 10 / sqrt 3, centre below the chord): two corners of 60 degrees, the rest smooth. The smooth
  // template does not take it (its pieces at the corners fold); the usual template's fallback would
  // put a third corner on the arc (180 degrees). The two-corner template keeps each corner in one
  // piece, and its two interior points are where three pieces meet.
  const double radius = 10 / std::sqrt(3.0), below = radius / 2;
  Ring cap{{0, 0}, {10, 0}};
  for (int k = 1; k < 12; ++k) {
    const double t = (30 + 10 * k) * M_PI / 180;
    cap.push_back({5 + radius * std::cos(t), -below + radius * std::sin(t)});
  }
  const Region part(cap, {}, kQ);
  CHECK_FALSE(smooth_template(part));
  REQUIRE(template_applies(part));
  REQUIRE(two_corner_template(part));
  REQUIRE(two_corner_improves(part));
  CHECK(template_pieces(part).size() == 3);  // by default the usual template, a corner on the arc
  const std::vector<QuadPiece> pieces = template_pieces(part, {}, true);
  REQUIRE(pieces.size() == 4);
  double area = 0;
  std::map<std::pair<double, double>, int> interior;  // a corner off the boundary, and how many pieces hold it
  int holding_p = 0, holding_q = 0;
  for (const QuadPiece& piece : pieces) {
    area += signed_area(piece.ring);
    check_corner_angles(piece);
    for (int k = 0; k < 4; ++k) {
      const Point2 v = piece.ring[static_cast<size_t>(piece.corners[static_cast<size_t>(k)])];
      holding_p += v == Point2{0, 0};
      holding_q += v == Point2{10, 0};
      const double r = std::hypot(v.x - 5, v.y + below);
      const bool on_boundary = std::fabs(v.y) < 1e-12 || std::fabs(r - radius) < 1e-6;  // (samples on the lattice)
      if (!on_boundary) ++interior[{v.x, v.y}];
    }
    // Every vertex of a piece on the boundary lies on the line or on the circle (arc samples kept).
    for (const Point2& v : piece.ring) {
      const double r = std::hypot(v.x - 5, v.y + below);
      CHECK((std::fabs(v.y) < 1e-12 || std::fabs(r - radius) < 1e-6 || r < radius - 1e-3));
    }
  }
  CHECK(area == Approx(part.area()).epsilon(1e-9));
  CHECK(holding_p == 1);  // each corner kept whole: a corner of one piece only
  CHECK(holding_q == 1);
  REQUIRE(interior.size() == 2);
  for (const auto& [point, count] : interior) CHECK(count == 3);
}

TEST_CASE("a long part with a rounded end gets the smooth template, its inner corners inset from the sides",
          "[region][block][arc]") {
  // A finger 2 wide and 7 long whose end is two quarter-round fillets (radius 0.8) and a short flat:
  // two corners (the cut across its top), the rest smooth. Halfway to the centroid, the inner corners
  // would fold the side pieces (a spoke from a fillet's middle nearly along the side); inset from the
  // rectangle's sides instead, every piece is a convex quadrilateral with angles in [20, 160] degrees,
  // and no piece has a corner at a fillet's tangent join (where a quad would meet the boundary at 170).
  Ring finger{{2, 7}, {0, 7}, {0, 0.8}};
  for (int k = 1; k < 6; ++k) finger.push_back({0.8 - 0.8 * std::cos(k * M_PI / 12), 0.8 - 0.8 * std::sin(k * M_PI / 12)});
  finger.push_back({0.8, 0});
  finger.push_back({1.2, 0});
  for (int k = 1; k < 6; ++k) finger.push_back({1.2 + 0.8 * std::sin(k * M_PI / 12), 0.8 - 0.8 * std::cos(k * M_PI / 12)});
  finger.push_back({2, 0.8});
  const Region part(finger, {}, kQ);
  REQUIRE(template_applies(part));
  REQUIRE(smooth_template(part));
  const std::vector<QuadPiece> pieces = template_pieces(part);
  REQUIRE(pieces.size() == 5);
  double area = 0;
  for (const QuadPiece& piece : pieces) {
    area += signed_area(piece.ring);
    check_corner_angles(piece);
    for (int k = 0; k < 4; ++k) {
      const Point2 v = piece.ring[static_cast<size_t>(piece.corners[static_cast<size_t>(k)])];
      for (const Point2 join : {Point2{0, 0.8}, Point2{0.8, 0}, Point2{1.2, 0}, Point2{2, 0.8}}) {
        CHECK(std::hypot(v.x - join.x, v.y - join.y) > 0.1);
      }
    }
  }
  CHECK(area == Approx(part.area()).epsilon(1e-9));
  // The inner quadrilateral spans most of the finger's length: its corners as far from the ends as
  // from the sides (a quarter of the width), not halfway to the centroid.
  double low = 1e9, high = -1e9;
  for (const Point2& p : pieces.back().ring) low = std::min(low, p.y), high = std::max(high, p.y);
  CHECK(high - low > 5.0);
}

namespace {

// An L (legs 4 wide, arms reaching 10) whose reflex corner at (4, 4) is filleted with radius 2: the
// arc's samples turn 15 degrees inwards each (side vertices), its ends meet the edges tangentially.
Ring filleted_l() {
  Ring ring{{0, 0}, {10, 0}, {10, 4}};
  for (int k = 0; k <= 6; ++k) ring.push_back({6 - 2 * std::sin(k * M_PI / 12), 6 - 2 * std::cos(k * M_PI / 12)});
  ring.push_back({4, 10});
  ring.push_back({0, 10});
  return ring;
}

}  // namespace

TEST_CASE("concave arcs: runs, their open ends, and the template on a fillet's corner piece", "[region][block][arc]") {
  // The fillet is one concave run of 90 degrees, open at both ends (the edges run on 4 beyond it).
  const Ring l = filleted_l();
  std::vector<ArcRun> runs = concave_runs(l);
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].turn == Approx(M_PI / 2).epsilon(1e-9));
  CHECK(l[runs[0].first].x == Approx(6.0));  // (6, 4): the tangent join with the lower edge
  CHECK(l[runs[0].last].y == Approx(6.0));   // (4, 6): with the upright one
  CHECK(runs[0].open_before);
  CHECK(runs[0].open_after);
  CHECK_FALSE(template_applies(Region(l, {}, kQ)));
  // A side vertex turned a little inwards (rounding to the lattice) is no concave run: a part that is
  // not convex only so is no fillet's corner piece (the search and the template's reward tell them
  // apart by this).
  const Ring dented{{0, 0}, {2, 0.01}, {4, 0}, {4, 4}, {0, 4}};
  CHECK(concave_runs(dented).empty());
  // A square with the same quarter circle cut from one corner: the run is closed at both ends (the
  // square's corners follow it at once), so the template applies: five quads around a centre, the
  // five-valent vertex such a part needs, its spokes clear of the arc.
  Ring notched{{0, 0}, {4, 0}, {4, 2}};
  for (int k = 1; k < 6; ++k) notched.push_back({4 - 2 * std::sin(k * M_PI / 12), 4 - 2 * std::cos(k * M_PI / 12)});
  notched.push_back({2, 4});
  notched.push_back({0, 4});
  runs = concave_runs(notched);
  REQUIRE(runs.size() == 1);
  CHECK_FALSE(runs[0].open_before);
  CHECK_FALSE(runs[0].open_after);
  const Region part(notched, {}, kQ);
  REQUIRE(template_applies(part));
  const std::vector<QuadPiece> pieces = template_pieces(part);
  REQUIRE(pieces.size() == 5);
  double area = 0;
  for (const QuadPiece& piece : pieces) {
    area += signed_area(piece.ring);
    CHECK(signed_area(piece.ring) > 0);
    // The centre is at least a radius's half from the arc's circle (centre (4, 4), radius 2).
    const Point2 c = piece.ring[static_cast<size_t>(piece.corners[2])];
    CHECK(std::hypot(c.x - 4, c.y - 4) > 2.5);
  }
  CHECK(area == Approx(part.area()).epsilon(1e-9));
  // A deeper notch (a half circle between the corners) is no side of a template.
  Ring half{{0, 0}, {6, 0}, {6, 4}};
  for (int k = 1; k < 12; ++k) half.push_back({5 + std::cos(k * M_PI / 12), 4 - std::sin(k * M_PI / 12)});
  half.push_back({4, 4});
  half.push_back({0, 4});
  runs = concave_runs(half);
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].turn > kClosedRunLimit);  // 165 degrees (its ends are corners)
  CHECK_FALSE(template_applies(Region(half, {}, kQ)));
}

namespace {

// A 10 x 6 rectangle whose top-right corner is rounded with radius 2 (centre (8, 4); arc samples every
// 15 degrees, side vertices): the arc runs from (10, 4) to (8, 6), meeting both edges tangentially.
Ring rounded_corner_rectangle() {
  Ring ring{{0, 0}, {10, 0}};
  for (int k = 0; k <= 6; ++k) ring.push_back({8 + 2 * std::cos(k * M_PI / 12), 4 + 2 * std::sin(k * M_PI / 12)});
  ring.push_back({0, 6});
  return ring;
}

}  // namespace

TEST_CASE("convex arcs: a fillet running on into straight edges is cut square at its ends, its sector is no such run",
          "[region][block][arc]") {
  const Ring rounded = rounded_corner_rectangle();
  std::vector<ArcRun> runs = convex_runs(rounded);
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].turn == Approx(M_PI / 2).epsilon(1e-9));
  CHECK(rounded[runs[0].first].y == Approx(4.0));  // (10, 4)
  CHECK(rounded[runs[0].last].x == Approx(8.0));   // (8, 6)
  CHECK(runs[0].open_before);
  CHECK(runs[0].open_after);
  CHECK(open_convex_run(rounded));
  // Three corners and the fillet: the usual template would take it whole into a side; the policies
  // cut it (the template stays legal: a replayed decomposition that used it still replays).
  const Region part(rounded, {}, kQ);
  CHECK(fillet_needs_cuts(part));
  CHECK(template_applies(part));
  // The same rectangle with its top-left corner chamfered has four corners (two of 135 degrees, within
  // the default rules): no block while the fillet lies open in its side.
  Ring chamfered(rounded.begin(), rounded.end() - 1);
  chamfered.push_back({2, 6});
  chamfered.push_back({0, 4});
  CHECK_FALSE(is_block(Region(chamfered, {}, kQ)));
  // Its sector, cut square at both ends (corners (8, 4), (10, 4), (8, 6)): the run is closed at both
  // ends, so it is no open fillet; the template finishes it (three quads around a three-valent centre).
  Ring sector{{8, 4}};
  for (int k = 0; k <= 6; ++k) sector.push_back({8 + 2 * std::cos(k * M_PI / 12), 4 + 2 * std::sin(k * M_PI / 12)});
  runs = convex_runs(sector);
  REQUIRE(runs.size() == 1);
  CHECK_FALSE(runs[0].open_before);
  CHECK_FALSE(runs[0].open_after);
  const Region sector_part(sector, {}, kQ);
  CHECK_FALSE(fillet_needs_cuts(sector_part));
  CHECK(template_pieces(sector_part).size() == 3);
  // A run of rounding (side vertices turned a little) is none; nor is a disk's (no vertex outside it).
  CHECK(convex_runs(Ring{{0, 0}, {2, -0.01}, {4, 0}, {4, 4}, {0, 4}}).empty());
  Ring disk;
  for (int k = 0; k < 24; ++k) disk.push_back({std::cos(k * M_PI / 12), std::sin(k * M_PI / 12)});
  CHECK(convex_runs(disk).empty());
  // A fillet of more than kOpenConvexMax rounds an acute corner (cut square at its ends it would leave
  // a sharp corner at its centre): it stays in a side. A wedge of 30 degrees whose tip is rounded (150).
  // The tip's circle (radius 1) sits at (10 + d, 0), d = 1 / sin 15: the sides' lines meet at
  // (10 + 2 d, 0); they run from its tangent points (at -75 and 75 degrees) back to x = 0.
  const double half = 15 * M_PI / 180, d = 1 / std::sin(half), y0 = std::tan(half) * (10 + 2 * d);
  Ring wedge{{0, -y0}};
  for (int k = 0; k <= 10; ++k) {
    const double a = -(M_PI / 2 - half) + k * (M_PI - 2 * half) / 10;  // lower tangent point, round the tip
    wedge.push_back({10 + d + std::cos(a), std::sin(a)});
  }
  wedge.push_back({0, y0});
  runs = convex_runs(wedge);
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].turn > kOpenConvexMax);
  CHECK_FALSE(open_convex_run(wedge));
}
