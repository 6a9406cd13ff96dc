// The block model of a general decomposition: shared vertices, imprinted T-junctions, four sides.
#include "core/mesh/block_model.h"

#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "support/mesh_fixtures.h"

using namespace autoblock;

namespace {

constexpr double kQ = 1e-7;

FinishedRegion block(int id, const Ring& ring) {
  return test::finished_block(id, ring, kQ);
}

// A long block under two short ones: (1, 1) is a T-junction on the long block's top side.
RegionDecomposition t_junction() {
  RegionDecomposition d;
  d.status = EpisodeStatus::Complete;
  d.finished.push_back(block(0, Ring{{0, 0}, {2, 0}, {2, 1}, {0, 1}}));
  d.finished.push_back(block(1, Ring{{0, 1}, {1, 1}, {1, 2}, {0, 2}}));
  d.finished.push_back(block(2, Ring{{1, 1}, {2, 1}, {2, 2}, {1, 2}}));
  return d;
}

int edge_uses(const BlockModel& m, size_t e) {
  int uses = 0;
  for (const ModelBlock& b : m.blocks) {
    for (const ModelSide& s : b.sides) uses += static_cast<int>(std::count(s.edges.begin(), s.edges.end(), static_cast<int>(e)));
  }
  return uses;
}

}  // namespace

TEST_CASE("block model: shared vertices and edges, a T-junction imprinted into the side it lies on", "[mesh][block_model]") {
  const BlockModel m = block_model(t_junction(), BlockRules{}, kQ);
  CHECK(m.parts == 3);
  REQUIRE(m.blocks.size() == 3);
  CHECK(m.vertices.size() == 8);  // the corners of the three squares; (1, 0) is none
  // The long block's top side (side 2, from (2, 1) to (0, 1)) holds two edges, split at (1, 1).
  const ModelBlock& bottom = m.blocks[0];
  size_t top_side = 4;
  for (size_t k = 0; k < 4; ++k) {
    if (m.side_length(bottom.sides[k]) == Approx(2.0) && bottom.sides[k].edges.size() == 2) top_side = k;
  }
  REQUIRE(top_side < 4);
  // Opposite: the bottom side, one edge of length 2.
  CHECK(bottom.sides[(top_side + 2) % 4].edges.size() == 1);
  CHECK(m.side_length(bottom.sides[(top_side + 2) % 4]) == Approx(2.0));
  // Every edge bounds one or two pieces; the boundary edges add up to the face's perimeter (8).
  double boundary = 0.0;
  for (size_t e = 0; e < m.edges.size(); ++e) {
    const int uses = edge_uses(m, e);
    CHECK((uses == 1 || uses == 2));
    if (uses == 1) boundary += m.edges[e].length;
  }
  CHECK(boundary == Approx(8.0));
}

TEST_CASE("block model: a T-junction several quanta off the side it lies on is imprinted at the wide tolerance", "[mesh][block_model]") {
  // The two upper squares' shared corner 7 quanta above the long block's top side (where many cuts end
  // on one line, each splitting it at a point rounded to the lattice, the drift adds up: 7.1 quanta
  // measured on a perforated disk of 89 holes). Imprinted, every edge bounds one or two pieces and the
  // boundary is the face's perimeter (8); not imprinted, the top side and the squares' bottoms each
  // bound one piece (12).
  RegionDecomposition d;
  d.status = EpisodeStatus::Complete;
  const double y = 1.0 + 7.0 * kQ;
  d.finished.push_back(block(0, Ring{{0, 0}, {2, 0}, {2, 1}, {0, 1}}));
  d.finished.push_back(block(1, Ring{{0, 1}, {1, y}, {1, 2}, {0, 2}}));
  d.finished.push_back(block(2, Ring{{1, y}, {2, 1}, {2, 2}, {1, 2}}));
  auto boundary = [](const BlockModel& m) {
    double length = 0.0;
    for (size_t e = 0; e < m.edges.size(); ++e) {
      const int uses = edge_uses(m, e);
      CHECK((uses == 1 || uses == 2));
      if (uses == 1) length += m.edges[e].length;
    }
    return length;
  };
  CHECK(boundary(block_model(d, BlockRules{}, kQ)) == Approx(12.0));
  const BlockModel wide = block_model(d, BlockRules{}, kQ, false, FeetSnap::near, kWideModelToleranceQuanta);
  REQUIRE(wide.blocks.size() == 3);
  CHECK(boundary(wide) == Approx(8.0));
}

TEST_CASE("block model: a template's pieces share their spokes and midpoints", "[mesh][block_model]") {
  RegionDecomposition d;
  d.status = EpisodeStatus::Complete;
  FinishedRegion triangle;
  triangle.region = Region(Ring{{0, 0}, {6, 0}, {0, 6}}, {}, kQ);
  triangle.is_template = true;
  d.finished.push_back(triangle);
  const BlockModel m = block_model(d, BlockRules{}, kQ);
  REQUIRE(m.blocks.size() == 3);
  CHECK(m.vertices.size() == 7);  // 3 corners, 3 midpoints, the centroid
  CHECK(m.edges.size() == 9);     // 6 half sides, 3 spokes
  int shared = 0;
  for (size_t e = 0; e < m.edges.size(); ++e) shared += edge_uses(m, e) == 2;
  CHECK(shared == 3);
  for (const ModelBlock& b : m.blocks) CHECK(b.from_template);
}

TEST_CASE("block model: an O-grid's hole is four edges along its arc, each a quarter turn", "[mesh][block_model][arc]") {
  // A 10 x 6 plate with a round hole of radius 1.5 at (5, 3), as the face reader gives it: the circle
  // (clockwise: a hole) and its circumscribed polygon.
  FaceArcs arcs;
  CircularArc circle;
  circle.center = {5, 3};
  circle.radius = 1.5;
  circle.sweep = -2.0 * M_PI;
  circle.outside = true;
  arcs.arcs = {circle};
  arcs.tolerance = 4.0 * kQ;
  Ring hole = polygonise_arc(circle);
  hole.pop_back();
  RegionDecomposition d;
  d.status = EpisodeStatus::Complete;
  FinishedRegion plate;
  plate.region = Region(Ring{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {hole}, kQ);
  plate.is_template = true;
  REQUIRE(ogrid_template(plate.region));
  d.finished.push_back(plate);
  BlockModel m = block_model(d, BlockRules{}, kQ);
  REQUIRE(m.blocks.size() == 12);
  const size_t before = m.edges.size();
  merge_arc_chains(m, arcs);
  // The hole's 24 chords became 4 edges (one per ring piece), the others stay as they were.
  CHECK(m.edges.size() == before - 20);
  int on_arc = 0;
  double sweep = 0.0, length = 0.0;
  for (size_t e = 0; e < m.edges.size(); ++e) {
    if (m.edges[e].arc < 0) continue;
    ++on_arc;
    sweep += m.edges[e].arc_sweep;
    length += m.edges[e].length;
    CHECK(edge_uses(m, e) == 1);
    // The spokes run to the hole's vertices nearest the box corners, near the diagonals.
    CHECK(std::fabs(m.edges[e].arc_sweep) > 0.25 * M_PI);
    CHECK(std::fabs(m.edges[e].arc_sweep) < 0.75 * M_PI);
  }
  CHECK(on_arc == 4);
  CHECK(sweep == Approx(-2.0 * M_PI));                   // once round, clockwise
  CHECK(length == Approx(region_perimeter(Region(hole, {}, kQ))));  // the chords' lengths
  // Every block still has four sides of at least one edge, chained end to end.
  for (const ModelBlock& b : m.blocks) {
    for (size_t k = 0; k < 4; ++k) {
      const ModelSide& side = b.sides[k];
      REQUIRE_FALSE(side.edges.empty());
      const ModelEdge& last = m.edges[static_cast<size_t>(side.edges.back())];
      const ModelEdge& next = m.edges[static_cast<size_t>(b.sides[(k + 1) % 4].edges.front())];
      CHECK((side.forward.back() ? last.b : last.a) == (b.sides[(k + 1) % 4].forward.front() ? next.a : next.b));
    }
  }
}

TEST_CASE("block model: two templates' feet a hair apart on their shared side are made one", "[mesh][block_model]") {
  // Two triangles on the side (0, 0)-(10, 0), each a template: a spoke of each meets that side where
  // the perpendicular from its centre does. Apexes nearly mirrored put the two feet a hair apart;
  // far from mirrored, a fair way apart.
  auto triangles = [](double lower_apex_x) {
    RegionDecomposition d;
    d.status = EpisodeStatus::Complete;
    for (const Ring& ring : {Ring{{0, 0}, {10, 0}, {5, 6}}, Ring{{10, 0}, {0, 0}, {lower_apex_x, -6}}}) {
      FinishedRegion t;
      t.id = static_cast<int>(d.finished.size());
      t.region = Region(ring, {}, kQ);
      t.is_template = true;
      d.finished.push_back(t);
    }
    return d;
  };
  auto shortest_edge = [](const BlockModel& m) {
    double shortest = 1e300;
    for (const ModelEdge& e : m.edges) shortest = std::min(shortest, e.length);
    return shortest;
  };
  auto check_pieces = [](const BlockModel& m) {
    REQUIRE(m.blocks.size() == 6);
    for (size_t e = 0; e < m.edges.size(); ++e) {
      const int uses = edge_uses(m, e);
      CHECK((uses == 1 || uses == 2));
    }
  };
  SECTION("a hair apart: one foot") {
    const RegionDecomposition d = triangles(5.05);
    const BlockModel as_placed = block_model(d, BlockRules{}, kQ, false, FeetSnap::placed);
    check_pieces(as_placed);
    CHECK(as_placed.snapped_feet == 0);
    // The two feet and the hair-thin edge between them.
    CHECK(shortest_edge(as_placed) > 0.0);
    CHECK(shortest_edge(as_placed) < 0.01 * 5.0);
    // 4 corners, 2 + 2 feet on the outer sides, 2 on (0, 0)-(10, 0), 2 centres.
    CHECK(as_placed.vertices.size() == 12);
    const BlockModel snapped = block_model(d, BlockRules{}, kQ);
    check_pieces(snapped);
    CHECK(snapped.snapped_feet == 1);
    CHECK(snapped.vertices.size() == 11);
    CHECK(shortest_edge(snapped) > 2.0);
    // The shared side is two edges, each used by one piece of either triangle.
    int shared = 0;
    for (size_t e = 0; e < snapped.edges.size(); ++e) {
      const Point2 a = snapped.vertices[static_cast<size_t>(snapped.edges[e].a)];
      const Point2 b = snapped.vertices[static_cast<size_t>(snapped.edges[e].b)];
      if (std::fabs(a.y) < 1e-9 && std::fabs(b.y) < 1e-9) {
        ++shared;
        CHECK(edge_uses(snapped, e) == 2);
      }
    }
    CHECK(shared == 2);
  }
  SECTION("a fair way apart: both feet") {
    const BlockModel m = block_model(triangles(8.0), BlockRules{}, kQ);
    check_pieces(m);
    CHECK(m.feet == FeetSnap::near);
    CHECK(m.snapped_feet == 0);
    CHECK(m.vertices.size() == 12);
    CHECK(shortest_edge(m) > 0.05 * 5.0);
  }
  SECTION("a fair way apart, made one by the far snap where the pieces keep their shape") {
    // The upper foot at x = 5, the lower one at 5.32 (the incentre of (10, 0), (0, 0), (5.5, -6)):
    // beyond the near snap (5 % of the upper spoke, 2.34), within 0.4 of the pieces' sides along the
    // shared side (5 and 5.32).
    const RegionDecomposition d = triangles(5.5);
    CHECK(block_model(d, BlockRules{}, kQ).snapped_feet == 0);
    const BlockModel far = block_model(d, BlockRules{}, kQ, false, FeetSnap::far);
    check_pieces(far);
    CHECK(far.feet == FeetSnap::far);
    CHECK(far.snapped_feet == 1);
    CHECK(far.vertices.size() == 11);
    // The foot that moved (the upper triangle's, first along x) stands on the other.
    int on_side = 0;
    for (const Point2& v : far.vertices) {
      if (std::fabs(v.y) > 1e-9) continue;
      ++on_side;
      const double a = std::hypot(5.5, 6.0);  // the lower triangle's side opposite (10, 0)
      if (v.x > 0.0 && v.x < 10.0) CHECK(v.x == Approx((10.0 * a + 10.0 * 5.5) / (a + 7.5 + 10.0)).margin(1e-3));
    }
    CHECK(on_side == 3);
    // Every piece keeps a convex quadrilateral of corners: the upper piece at (0, 0) opens at its
    // centre from 130 to 138 degrees (a sine of 0.67, against 0.77).
    for (const ModelBlock& block : far.blocks) {
      std::array<Point2, 4> q;
      for (size_t k = 0; k < 4; ++k) {
        const ModelSide& side = block.sides[k];
        const ModelEdge& e = far.edges[static_cast<size_t>(side.edges.front())];
        q[k] = far.vertices[static_cast<size_t>(side.forward.front() ? e.a : e.b)];
      }
      for (size_t k = 0; k < 4; ++k) {
        const Point2 o = q[k], a = q[(k + 1) % 4], b = q[(k + 3) % 4];
        const double sine = ((a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)) /
                            (std::hypot(a.x - o.x, a.y - o.y) * std::hypot(b.x - o.x, b.y - o.y));
        CHECK(sine > 0.55);
      }
    }
  }
  SECTION("the far snap refuses a move that would distort a piece") {
    // The lower foot at 6.84 (apex (8, -6)): 1.84 apart, within 0.4 of the sides of 5, but the upper
    // piece at (0, 0) would open at its centre to 168 degrees (a sine of 0.2).
    const BlockModel far = block_model(triangles(8.0), BlockRules{}, kQ, false, FeetSnap::far);
    check_pieces(far);
    CHECK(far.snapped_feet == 0);
    CHECK(far.vertices.size() == 12);
  }
  SECTION("too far apart for the far snap: both feet") {
    // The lower foot at 7.49: 2.49 apart, beyond 0.4 of the upper pieces' sides of 5.
    const BlockModel far = block_model(triangles(9.5), BlockRules{}, kQ, false, FeetSnap::far);
    check_pieces(far);
    CHECK(far.snapped_feet == 0);
    CHECK(far.vertices.size() == 12);
  }
}

TEST_CASE("block model: two cuts' ends a hair apart on the side their parts share are made one", "[mesh][block_model]") {
  // The line y = 1 across a 4 by 2 face: below it a cut at x = 2, above it one at x = 2 + gap. Each
  // end is a vertex of the two parts it divides and a T-junction on the side of a part across the line.
  auto blocks = [](double gap, bool lower_split, bool upper_split) {
    RegionDecomposition d;
    d.status = EpisodeStatus::Complete;
    const double x = 2.0 + gap;
    std::vector<Ring> rings{Ring{{2, 0}, {4, 0}, {4, 1}, {2, 1}}, Ring{{x, 1}, {4, 1}, {4, 2}, {x, 2}}, Ring{{0, 1}, {x, 1}, {x, 2}, {0, 2}}};
    // A split part puts its own vertex on a side that the move of the cut's end beside it would turn.
    if (lower_split) {
      rings.push_back(Ring{{0, 0}, {2, 0}, {2, 0.5}, {0, 0.5}});
      rings.push_back(Ring{{0, 0.5}, {2, 0.5}, {2, 1}, {0, 1}});
    } else {
      rings.push_back(Ring{{0, 0}, {2, 0}, {2, 1}, {0, 1}});
    }
    if (upper_split) {
      rings[1] = Ring{{x, 1}, {4, 1}, {4, 1.5}, {x, 1.5}};
      rings.push_back(Ring{{x, 1.5}, {4, 1.5}, {4, 2}, {x, 2}});
    }
    for (const Ring& r : rings) d.finished.push_back(block(static_cast<int>(d.finished.size()), r));
    return d;
  };
  auto near_x = [](const BlockModel& m, double x) {
    int count = 0;
    for (const Point2& v : m.vertices) count += std::fabs(v.y - 1.0) < 1e-9 && std::fabs(v.x - x) < 1e-9;
    return count;
  };
  auto check_edges = [](const BlockModel& m, double perimeter) {
    double boundary = 0.0, shortest = 1e300;
    for (size_t e = 0; e < m.edges.size(); ++e) {
      const int uses = edge_uses(m, e);
      CHECK((uses == 1 || uses == 2));
      if (uses == 1) boundary += m.edges[e].length;
      shortest = std::min(shortest, m.edges[e].length);
    }
    CHECK(boundary == Approx(perimeter));
    return shortest;
  };
  SECTION("a hair apart: one vertex") {
    const RegionDecomposition d = blocks(0.001, false, false);
    const BlockModel as_placed = block_model(d, BlockRules{}, kQ, false, FeetSnap::placed);
    CHECK(check_edges(as_placed, 12.0) == Approx(0.001));
    CHECK(as_placed.vertices.size() == 10);
    const BlockModel m = block_model(d, BlockRules{}, kQ);
    CHECK(m.snapped_feet == 1);
    CHECK(m.vertices.size() == 9);
    CHECK(check_edges(m, 12.0) == Approx(1.0).margin(0.01));  // the cuts, 1 long
    CHECK(near_x(m, 2.0) + near_x(m, 2.001) == 1);
  }
  SECTION("the end whose move would leave another part's vertex off its side stays; the other moves") {
    // The part left of the lower cut is split at y = 0.5: (2, 0.5) lies on the lower cut. Moving
    // (2, 1) would turn the cut about (2, 0) and leave (2, 0.5) off it; the upper end moves instead.
    const BlockModel m = block_model(blocks(0.001, true, false), BlockRules{}, kQ);
    CHECK(m.snapped_feet == 1);
    CHECK(near_x(m, 2.0) == 1);
    CHECK(near_x(m, 2.001) == 0);
    CHECK(check_edges(m, 12.0) > 0.4);
  }
  SECTION("where neither end may move, both stay") {
    const BlockModel m = block_model(blocks(0.001, true, true), BlockRules{}, kQ);
    CHECK(m.snapped_feet == 0);
    CHECK(near_x(m, 2.0) == 1);
    CHECK(near_x(m, 2.001) == 1);
    CHECK(check_edges(m, 12.0) == Approx(0.001));
  }
  SECTION("a fair way apart: both stay") {
    const BlockModel m = block_model(blocks(0.2, false, false), BlockRules{}, kQ, false, FeetSnap::far);
    CHECK(m.snapped_feet == 0);
    CHECK(check_edges(m, 12.0) == Approx(0.2));
  }
  SECTION("a vertex on the face's boundary stays; the one inside moves to it") {
    // An L: the face's reflex corner (2.001, 1) is the upper part's corner, a hair from the lower cut's
    // end (2, 1), which moves onto it.
    RegionDecomposition d;
    d.status = EpisodeStatus::Complete;
    d.finished.push_back(block(0, Ring{{0, 0}, {2, 0}, {2, 1}, {0, 1}}));
    d.finished.push_back(block(1, Ring{{2, 0}, {4, 0}, {4, 1}, {2, 1}}));
    d.finished.push_back(block(2, Ring{{0, 1}, {2.001, 1}, {2.001, 2}, {0, 2}}));
    const BlockModel m = block_model(d, BlockRules{}, kQ);
    CHECK(m.snapped_feet == 1);
    CHECK(near_x(m, 2.0) == 0);
    CHECK(near_x(m, 2.001) == 1);
    CHECK(check_edges(m, 12.0) > 0.9);
  }
}
