#include "core/graph/region_graph.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "core/data/arc_generator.h"
#include "core/geometry/part_boundary.h"
#include "core/geometry/rectilinear_polygon.h"
#include "core/geometry/tolerance.h"
#include "core/io/input_face.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

// Inputs: graphs a and b; tolerance. Output: true when each node of a has a node of b of the same
// kind within the tolerance, and the other way round.
bool same_nodes(const PartGraph& a, const PartGraph& b, double tolerance) {
  auto covered = [tolerance](const PartGraph& x, const PartGraph& y) {
    for (size_t i = 0; i < x.positions.size(); ++i) {
      bool found = false;
      for (size_t j = 0; j < y.positions.size() && !found; ++j) {
        found = x.features[i] == y.features[j] && std::fabs(x.positions[i].x - y.positions[j].x) <= tolerance &&
                std::fabs(x.positions[i].y - y.positions[j].y) <= tolerance;
      }
      if (!found) return false;
    }
    return true;
  };
  return covered(a, b) && covered(b, a);
}

// Inputs: region, its graph. Output: "" when the graph keeps region_graph's contract (model vertices
// first, at the loops' vertices, in order; every edge inside the region or along its boundary; the
// pseudo-coordinates in [0, 1]), else the first violation.
std::string region_graph_problem(const Region& region, const PartGraph& g) {
  size_t v = 0;
  for (const Ring& loop : region.loops()) {
    for (const Point2& p : loop) {
      if (v >= g.vertex_nodes.size() || g.vertex_nodes[v] != static_cast<int>(v)) return "vertex_nodes not 0..V-1";
      if (!(g.positions[v] == p)) return "a model vertex off its loop vertex";
      if (g.features[v][2] != 1.f) return "a model vertex without the corner feature";
      ++v;
    }
  }
  if (g.vertex_nodes.size() != v) return "vertex_nodes and the loops' vertices differ in count";
  if (g.pseudo.size() != g.edges.size() || g.features.size() != g.positions.size()) return "array sizes differ";
  const double q = region.quantum();
  for (size_t e = 0; e < g.edges.size(); ++e) {
    const Point2 a = g.positions[static_cast<size_t>(g.edges[e][0])], b = g.positions[static_cast<size_t>(g.edges[e][1])];
    // The midpoint of an edge is in the region (not in a hole), or on its boundary.
    for (const float c : g.pseudo[e]) {
      if (!(c >= 0.f && c <= 1.f)) return "a pseudo-coordinate outside [0, 1]";
    }
    const Point2 m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
    bool on_boundary = false;
    for (const Ring& loop : region.loops()) {
      for (size_t k = 0; k < loop.size() && !on_boundary; ++k) {
        const Point2 p = loop[k], r = loop[(k + 1) % loop.size()];
        const double length = std::hypot(r.x - p.x, r.y - p.y);
        const double off = std::fabs((r.x - p.x) * (m.y - p.y) - (r.y - p.y) * (m.x - p.x)) / length;
        const double along = ((m.x - p.x) * (r.x - p.x) + (m.y - p.y) * (r.y - p.y)) / length;
        on_boundary = off <= 1e-3 * q && along >= -1e-3 * q && along <= length + 1e-3 * q;
      }
    }
    if (on_boundary) continue;
    if (!point_in_ring(m, region.outer())) return "an edge outside the outer loop";
    for (const Ring& hole : region.holes()) {
      if (point_in_ring(m, hole)) return "an edge across a hole";
    }
  }
  return "";
}


}  // namespace

TEST_CASE("region_graph on a rectilinear part is part_graph's graph", "[graph][region]") {
  // Generated faces with and without holes: the same nodes (kinds, and positions within the region's
  // quantum: its vertices are on its lattice) and as many edges (a triangulation of the same points
  // and constraints; which diagonal of four points on a circle is taken may differ).
  for (const bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    for (const GeneratedShape& s : test::generated_shapes(30, holes ? 22 : 21, options)) {
      const GridFace face = make_grid_face(s.polygon);
      std::vector<Ring> loops;
      for (const CornerRing& loop : part_boundary(face.whole)) {
        Ring& ring = loops.emplace_back();
        for (const Corner& c : loop) ring.push_back({face.grid->xs[static_cast<size_t>(c.i)], face.grid->ys[static_cast<size_t>(c.j)]});
      }
      const Region region(loops[0], std::vector<Ring>(loops.begin() + 1, loops.end()),
                          tolerance_for_size(ring_bbox(loops[0]).longer_side()));
      const PartGraph g = region_graph(region), p = part_graph(face.whole);
      REQUIRE(region_graph_problem(region, g) == "");
      CHECK(g.node_count() == p.node_count());
      CHECK(g.vertex_nodes.size() == p.vertex_nodes.size());
      CHECK(g.edge_count() == p.edge_count());
      CHECK(same_nodes(g, p, region.quantum()));
    }
  }
}

TEST_CASE("region_graph of general faces, with holes and arcs, and their pieces: valid and small", "[graph][region]") {
  // Polygons and chamfered unions with and without holes, faces with arcs (their chords), and the
  // pieces of their first cuts: the contract holds and a part of V vertices has at most 5 V nodes
  // (an edge is at most the bounding box's diagonal, sqrt(2) times its longer side: 4 points).
  std::vector<Region> faces;
  for (int i = 0; i < 12; ++i) {
    faces.push_back(test::region_of(test::general_polygon(100 + i, i % 2 ? GeneralKind::Chamfered : GeneralKind::Polygon, i % 3 == 0)));
  }
  std::mt19937_64 rng(31);
  for (int i = 0; i < 10; ++i) {
    const ArcFace arc_face = random_arc_face(rng, static_cast<ArcKind>(i % kArcKinds), 1.0 + i);
    faces.push_back(input_face_from_occt(arc_face.face, arc_face.name).region);
  }
  int parts = 0;
  for (const Region& face : faces) {
    for (const Region& part : test::face_and_first_pieces(face, 4)) {
      const PartGraph g = region_graph(part);
      INFO("part of " << part.vertex_count() << " vertices, " << part.holes().size() << " holes");
      REQUIRE(region_graph_problem(part, g) == "");
      CHECK(g.node_count() <= 5 * part.vertex_count());
      CHECK(g.edge_count() >= 2 * (g.node_count() - 1));  // connected: a spanning tree's edges, both ways
      ++parts;
    }
  }
  CHECK(parts > 60);
}

TEST_CASE("region_graph does not depend on the drawing's units, and refuses an empty region", "[graph][region]") {
  const Ring outer{{0, 0}, {7, 1}, {9, 5}, {3, 8}, {-2, 4}};
  const Ring hole{{2, 3}, {4, 3}, {3, 5}};
  const PartGraph small = region_graph(Region(outer, {hole}, 1e-6));
  Ring big_outer, big_hole;
  for (const Point2& p : outer) big_outer.push_back({1000.0 * p.x + 50.0, 1000.0 * p.y - 20.0});
  for (const Point2& p : hole) big_hole.push_back({1000.0 * p.x + 50.0, 1000.0 * p.y - 20.0});
  const PartGraph big = region_graph(Region(big_outer, {big_hole}, 1e-3));
  REQUIRE(big.node_count() == small.node_count());
  REQUIRE(big.edges == small.edges);
  CHECK(big.features == small.features);
  for (size_t e = 0; e < small.pseudo.size(); ++e) {
    CHECK(big.pseudo[e][0] == Approx(small.pseudo[e][0]).margin(1e-5));
    CHECK(big.pseudo[e][1] == Approx(small.pseudo[e][1]).margin(1e-5));
  }
  CHECK_THROWS_AS(region_graph(Region()), std::invalid_argument);
}
