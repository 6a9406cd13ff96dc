#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/baselines/random_policy.h"
#include "core/common/error.h"
#include "core/data/thin_features.h"
#include "core/env/episode.h"
#include "core/geometry/part_boundary.h"
#include "core/graph/part_graph.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

// Inputs: part, p. Output: true when p lies on one of the part's boundary segments.
bool on_boundary(const Part& part, const std::vector<CornerRing>& loops, Point2 p) {
  const Grid& grid = part.grid();
  for (const CornerRing& loop : loops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const Corner& a = loop[k];
      const Corner& b = loop[(k + 1) % loop.size()];
      const double ax = grid.xs[static_cast<size_t>(a.i)], ay = grid.ys[static_cast<size_t>(a.j)];
      const double bx = grid.xs[static_cast<size_t>(b.i)], by = grid.ys[static_cast<size_t>(b.j)];
      if (ax == bx && p.x == ax && p.y >= std::min(ay, by) && p.y <= std::max(ay, by)) return true;
      if (ay == by && p.y == ay && p.x >= std::min(ax, bx) && p.x <= std::max(ax, bx)) return true;
    }
  }
  return false;
}

// Inputs: part, p not on its boundary. Output: true when p is inside the part (in one of its cells).
bool inside_cells(const Part& part, Point2 p) {
  const Grid& grid = part.grid();
  const auto i = std::upper_bound(grid.xs.begin(), grid.xs.end(), p.x) - grid.xs.begin() - 1;
  const auto j = std::upper_bound(grid.ys.begin(), grid.ys.end(), p.y) - grid.ys.begin() - 1;
  return part.contains(static_cast<int>(i), static_cast<int>(j));
}

// Inputs: part, its graph. Output: "" when the graph satisfies part_graph's contract, otherwise a
// description of the first violation.
std::string graph_problem(const Part& part, const PartGraph& g) {
  std::ostringstream out;
  const auto loops = part_boundary(part);
  const Grid& grid = part.grid();
  const size_t n = g.positions.size();
  if (g.features.size() != n) return "features and positions differ in size";
  if (g.pseudo.size() != g.edges.size()) return "pseudo and edges differ in size";
  // Model vertices: nodes 0..V-1 in part_boundary order, at the corners.
  size_t v = 0;
  for (const CornerRing& loop : loops) {
    for (const Corner& c : loop) {
      if (v >= g.vertex_nodes.size()) return "too few vertex_nodes";
      const int node = g.vertex_nodes[v];
      if (node < 0 || static_cast<size_t>(node) >= n) return "vertex node out of range";
      const Point2 p = g.positions[static_cast<size_t>(node)];
      if (!(p == Point2{grid.xs[static_cast<size_t>(c.i)], grid.ys[static_cast<size_t>(c.j)]})) {
        out << "model vertex " << v << " is at (" << p.x << ", " << p.y << "), not at its corner";
        return out.str();
      }
      ++v;
    }
  }
  if (v != g.vertex_nodes.size()) return "more vertex_nodes than corners";
  const std::set<int> vertex_set(g.vertex_nodes.begin(), g.vertex_nodes.end());
  if (vertex_set.size() != v) return "two model vertices share a node";
  // Features: one-hot, model vertex exactly at the corners, boundary on the boundary, interior inside.
  for (size_t k = 0; k < n; ++k) {
    const auto& f = g.features[k];
    const Point2 p = g.positions[k];
    if (f[0] + f[1] + f[2] != 1.f || std::count(f.begin(), f.end(), 1.f) != 1) return "a feature is not one-hot";
    const bool is_vertex = vertex_set.count(static_cast<int>(k)) > 0;
    if ((f[2] == 1.f) != is_vertex) return "feature (0,0,1) on a node that is not a model vertex, or missing";
    const bool boundary = on_boundary(part, loops, p);
    if (f[1] == 1.f && !boundary) {
      out << "edge node " << k << " at (" << p.x << ", " << p.y << ") is not on the boundary";
      return out.str();
    }
    if (f[0] == 1.f && (boundary || !inside_cells(part, p))) {
      out << "interior node " << k << " at (" << p.x << ", " << p.y << ") is not strictly inside";
      return out.str();
    }
  }
  // Edges: in range, no loops or duplicates, both ways; each edge's midpoint in the closed part
  // (an edge cannot cross a constraint, so an edge through a hole or outside has its midpoint there).
  std::set<std::pair<int, int>> edge_set;
  for (const auto& [a, b] : g.edges) {
    if (a < 0 || b < 0 || static_cast<size_t>(a) >= n || static_cast<size_t>(b) >= n || a == b) return "bad edge";
    if (!edge_set.insert({a, b}).second) return "duplicate edge";
  }
  size_t boundary_edges = 0;
  for (const auto& [a, b] : edge_set) {
    if (!edge_set.count({b, a})) return "an edge is missing its reverse";
    const Point2 pa = g.positions[static_cast<size_t>(a)], pb = g.positions[static_cast<size_t>(b)];
    const Point2 mid{0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)};
    const bool boundary = on_boundary(part, loops, mid);
    if (!boundary && !inside_cells(part, mid)) {
      out << "edge (" << pa.x << ", " << pa.y << ") - (" << pb.x << ", " << pb.y << ") lies outside the part";
      return out.str();
    }
    if (boundary && a < b) ++boundary_edges;
  }
  // Every node is used, and the edges form a triangulation of a domain with the part's holes:
  // 3 F = 2 E - E_boundary and Euler's V - E + F = 1 - holes.
  std::set<int> used;
  for (const auto& [a, b] : g.edges) used.insert(a);
  if (used.size() != n) return "an isolated node";
  const long undirected = static_cast<long>(edge_set.size() / 2);
  const long three_f = 2 * undirected - static_cast<long>(boundary_edges);
  if (three_f % 3 != 0) return "edge counts do not fit a triangulation";
  const long faces = three_f / 3;
  const long holes = static_cast<long>(loops.size()) - 1;
  if (static_cast<long>(n) - undirected + faces != 1 - holes) {
    out << "Euler characteristic " << static_cast<long>(n) - undirected + faces << ", expected " << 1 - holes;
    return out.str();
  }
  // Pseudo-coordinates: the formula, in [0,1].
  double m = 0;
  for (const auto& [a, b] : g.edges) {
    const Point2 pa = g.positions[static_cast<size_t>(a)], pb = g.positions[static_cast<size_t>(b)];
    m = std::max({m, std::abs(pa.x - pb.x), std::abs(pa.y - pb.y)});
  }
  for (size_t e = 0; e < g.edges.size(); ++e) {
    const Point2 pa = g.positions[static_cast<size_t>(g.edges[e][0])];
    const Point2 pb = g.positions[static_cast<size_t>(g.edges[e][1])];
    const double u = (pa.x - pb.x) / (2 * m) + 0.5, w = (pa.y - pb.y) / (2 * m) + 0.5;
    for (float value : g.pseudo[e]) {
      if (!(value >= 0.f && value <= 1.f)) return "pseudo outside [0,1]";
    }
    if (std::abs(g.pseudo[e][0] - u) > 1e-6 || std::abs(g.pseudo[e][1] - w) > 1e-6) return "pseudo off the formula";
  }
  return "";
}

Ring scaled(const Ring& ring, double s, Point2 shift) {
  Ring out;
  for (const Point2& p : ring) out.push_back({s * p.x + shift.x, s * p.y + shift.y});
  return out;
}

// Inputs: count, seed, options. Output: the non-rectangular parts met by random splitting
// episodes on that many generated faces: what the agent triangulates.
std::vector<Part> cut_pieces(int count, std::uint64_t seed, const GeneratorOptions& options) {
  std::vector<Part> parts;
  RandomPolicy policy(seed, /*splitting_only=*/true);
  for (const GeneratedShape& shape : test::generated_shapes(count, seed, options)) {
    Episode episode(make_grid_face(shape.polygon));
    while (episode.running()) {
      parts.push_back(episode.current_part());
      episode.step(policy.choose(episode));
    }
  }
  return parts;
}

}  // namespace

TEST_CASE("graph methods have names", "[graph]") {
  CHECK(graph_method_by_name(graph_method_name(GraphMethod::Bounded)) == GraphMethod::Bounded);
  CHECK(graph_method_by_name(graph_method_name(GraphMethod::Refined)) == GraphMethod::Refined);
  CHECK(std::string(graph_method_name(GraphMethod::Bounded)) == "bounded");
  CHECK_THROWS_AS(graph_method_by_name("fine"), InputError);
}

TEST_CASE("part_graph of the L-shape: corners first, in boundary order, then Steiner points", "[graph]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  const PartGraph g = part_graph(face.whole);
  const Ring corners = test::l_shape();  // counter-clockwise from the lowest-left corner
  REQUIRE(g.vertex_nodes.size() == 6);
  for (size_t k = 0; k < 6; ++k) {
    CHECK(g.vertex_nodes[k] == static_cast<int>(k));
    CHECK(g.positions[k] == corners[k]);
    CHECK(g.features[k] == std::array<float, 3>{0, 0, 1});
  }
  // Size bound 0.35 * 2 = 0.7: the two edges 2 long are split in three, the four 1 long in two.
  const auto edge_nodes = std::count(g.features.begin(), g.features.end(), std::array<float, 3>{0, 1, 0});
  CHECK(edge_nodes == 8);
  CHECK(g.node_count() == 14);
  // Refined (CGAL's Delaunay refinement), every unit edge gets split too.
  const PartGraph refined = part_graph(face.whole, GraphOptions{0.35, 0.125, 1000, GraphMethod::Refined});
  CHECK(std::count(refined.features.begin(), refined.features.end(), std::array<float, 3>{0, 1, 0}) >= 8);
  CHECK(graph_problem(face.whole, refined) == "");
  CHECK(graph_problem(face.whole, g) == "");
  CHECK(std::is_sorted(g.edges.begin(), g.edges.end()));
}

TEST_CASE("part_graph with no effective size bound: a rectangle keeps its corners only", "[graph]") {
  // The 2 x 1 rectangle: two right triangles (angles 26.6 and 63.4 degrees, above the 20.7 degree
  // bound), no edge encroached: 4 nodes and 5 edges, both ways.
  const GridFace face = test::grid_face_of({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  const PartGraph g = part_graph(face.whole, GraphOptions{10.0, 0.125, 0});
  CHECK(g.node_count() == 4);
  CHECK(g.edge_count() == 10);
  CHECK(graph_problem(face.whole, g) == "");
  // The edge from corner 0 (0,0) to corner 1 (2,0): the largest component over all edges is m = 2
  // (bottom edge and diagonal), so pseudo = ((0 - 2) / 4 + 0.5, (0 - 0) / 4 + 0.5) = (0, 0.5), and
  // the reverse edge (1, 0.5).
  const auto pseudo_of = [&g](int a, int b) {
    const auto it = std::find(g.edges.begin(), g.edges.end(), std::array<int, 2>{a, b});
    REQUIRE(it != g.edges.end());
    return g.pseudo[static_cast<size_t>(it - g.edges.begin())];
  };
  CHECK(pseudo_of(0, 1) == std::array<float, 2>{0.f, 0.5f});
  CHECK(pseudo_of(1, 0) == std::array<float, 2>{1.f, 0.5f});
  // Corner 1 (2,0) to corner 2 (2,1): (0 / 4 + 0.5, -1 / 4 + 0.5) = (0.5, 0.25).
  CHECK(pseudo_of(1, 2) == std::array<float, 2>{0.5f, 0.25f});
}

TEST_CASE("refined graphs with no effective size bound split the L-shape's encroached edges", "[graph]") {
  // The re-entrant corner (1,1) lies on the diametral circles of the long edges (0,0)-(2,0) and
  // (0,2)-(0,0) (centres (1,0) and (0,1), radius 1): CGAL's conforming refinement splits both at
  // their midpoints, and nothing else is needed. 8 nodes: 6 corners, (1,0) and (0,1) on edges.
  const GridFace face = test::grid_face_of(test::l_shape());
  const PartGraph g = part_graph(face.whole, GraphOptions{10.0, 0.125, 0, GraphMethod::Refined});
  CHECK(graph_problem(face.whole, g) == "");
  REQUIRE(g.node_count() == 8);
  std::vector<std::pair<double, double>> extra;
  for (int k = 6; k < 8; ++k) {
    CHECK(g.features[static_cast<size_t>(k)] == std::array<float, 3>{0, 1, 0});
    extra.emplace_back(g.positions[static_cast<size_t>(k)].x, g.positions[static_cast<size_t>(k)].y);
  }
  std::sort(extra.begin(), extra.end());
  CHECK((extra == std::vector<std::pair<double, double>>{{0, 1}, {1, 0}}));
  // Euler (checked above) then fixes the rest: 8 boundary edges, 13 edges, 6 triangles.
  CHECK(g.edge_count() == 26);
}

TEST_CASE("part_graph leaves holes empty", "[graph]") {
  const GridFace face = test::grid_face_of(test::square3(), {test::centre_hole()});
  const PartGraph g = part_graph(face.whole);
  CHECK(graph_problem(face.whole, g) == "");
  REQUIRE(g.vertex_nodes.size() == 8);
  // Nothing strictly inside the hole (1,2)^2, neither a node nor an edge's midpoint.
  auto in_hole = [](Point2 p) { return p.x > 1 && p.x < 2 && p.y > 1 && p.y < 2; };
  for (const Point2& p : g.positions) CHECK_FALSE(in_hole(p));
  for (const auto& [a, b] : g.edges) {
    const Point2 pa = g.positions[static_cast<size_t>(a)], pb = g.positions[static_cast<size_t>(b)];
    CHECK_FALSE(in_hole(Point2{0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)}));
  }
  // The hole's four corners are model vertices 4..7, clockwise from (1,1).
  CHECK(g.positions[4] == Point2{1, 1});
  CHECK(g.positions[5] == Point2{1, 2});
  CHECK(g.positions[6] == Point2{2, 2});
  CHECK(g.positions[7] == Point2{2, 1});
}

TEST_CASE("part_graph does not depend on the drawing's units or position", "[graph]") {
  const GeneratorOptions options;
  for (const GeneratedShape& shape : test::generated_shapes(20, 7, options)) {
    const PartGraph a = part_graph(make_grid_face(shape.polygon).whole);
    const double s = 1234.5;
    const Point2 shift{-5e3, 7e2};
    RectilinearPolygon big{scaled(shape.polygon.outer, s, shift), {}};
    const PartGraph b = part_graph(make_grid_face(big).whole);
    CHECK(a.node_count() == b.node_count());
    CHECK(a.edges == b.edges);
    if (a.pseudo.size() != b.pseudo.size()) continue;
    float worst = 0;
    for (size_t e = 0; e < a.pseudo.size(); ++e) {
      worst = std::max({worst, std::abs(a.pseudo[e][0] - b.pseudo[e][0]), std::abs(a.pseudo[e][1] - b.pseudo[e][1])});
    }
    CHECK(worst < 1e-5f);
  }
}

TEST_CASE("part_graph is deterministic", "[graph]") {
  const GeneratorOptions options{2, 10, true, 2, 12};
  for (const GeneratedShape& shape : test::generated_shapes(10, 3, options)) {
    const Part part = make_grid_face(shape.polygon).whole;
    const PartGraph a = part_graph(part), b = part_graph(part);
    CHECK(a.positions == b.positions);
    CHECK(a.edges == b.edges);
    CHECK(a.vertex_nodes == b.vertex_nodes);
  }
}

TEST_CASE("part_graph is a valid, small triangulation of generated faces and their cut pieces", "[graph]") {
  struct Set {
    const char* name;
    std::vector<Part> parts;
  };
  std::vector<Set> sets;
  for (bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    Set faces{holes ? "2-10 rectangles with holes" : "2-10 rectangles", {}};
    for (const GeneratedShape& s : test::generated_shapes(200, holes ? 12 : 11, options)) {
      faces.parts.push_back(make_grid_face(s.polygon).whole);
    }
    sets.push_back(std::move(faces));
    sets.push_back(Set{holes ? "cut pieces, with holes" : "cut pieces", cut_pieces(60, holes ? 14 : 13, options)});
  }
  GeneratorOptions large;
  large.min_rects = 11;
  large.max_rects = 40;
  Set big{"11-40 rectangles", {}};
  for (const GeneratedShape& s : test::generated_shapes(50, 15, large)) big.parts.push_back(make_grid_face(s.polygon).whole);
  sets.push_back(std::move(big));

  for (const Set& set : sets) {
    std::vector<int> nodes;
    for (const Part& part : set.parts) {
      const PartGraph g = part_graph(part);
      INFO(set.name << ", part with " << part.cell_count() << " cells");
      REQUIRE(graph_problem(part, g) == "");
      nodes.push_back(g.node_count());
    }
    std::sort(nodes.begin(), nodes.end());
    const int median = nodes[nodes.size() / 2], p90 = nodes[nodes.size() * 9 / 10], top = nodes.back();
    INFO(set.name << ": " << nodes.size() << " parts, nodes median " << median << ", 90% " << p90 << ", max " << top);
    const bool large_faces = std::string(set.name) == "11-40 rectangles";
    // Measured (bench_value_network): 2-10 rectangle faces and pieces have medians of 21-36 nodes
    // and at most 67; 11-40 rectangle faces a median of 50-62 and at most 130.
    CHECK(median <= (large_faces ? 100 : 45));
    CHECK(top <= (large_faces ? 250 : 120));
  }
}

TEST_CASE("refined graphs cap the refinement of thin parts", "[graph]") {
  // An L with arms 1 long and 0.001 thick: the 20.7 degree bound alone needs about 2000 nodes.
  const GridFace face = test::grid_face_of({{0, 0}, {1, 0}, {1, 0.001}, {0.001, 0.001}, {0.001, 1}, {0, 1}});
  GraphOptions refined;
  refined.method = GraphMethod::Refined;
  GraphOptions uncapped = refined;
  uncapped.max_nodes = 0;
  const PartGraph full = part_graph(face.whole, uncapped);
  CHECK(full.node_count() > 1500);
  CHECK(graph_problem(face.whole, full) == "");
  const PartGraph capped = part_graph(face.whole, refined);  // default cap: 1000 nodes
  CHECK(capped.node_count() <= 1000);
  CHECK(capped.node_count() >= 990);
  CHECK(graph_problem(face.whole, capped) == "");
  // Typical parts never reach the cap: the same graph with and without it.
  for (const GeneratedShape& shape : test::generated_shapes(20, 31, GeneratorOptions{})) {
    const Part part = make_grid_face(shape.polygon).whole;
    CHECK(part_graph(part, refined).edges == part_graph(part, uncapped).edges);
  }
}

TEST_CASE("bounded graphs stay small on thin parts", "[graph]") {
  // A 1:1000 strip: the long sides are split into three (size bound 0.35 x 1000), nothing else.
  const GridFace strip = test::grid_face_of({{0, 0}, {1000, 0}, {1000, 1}, {0, 1}});
  const PartGraph s = part_graph(strip.whole);
  CHECK(s.node_count() == 8);
  CHECK(graph_problem(strip.whole, s) == "");
  // An L with arms 1 long and 0.001 thick (about 2000 nodes refined): 6 corners, and 2 points on
  // each of the four long edges.
  const GridFace thin_l = test::grid_face_of({{0, 0}, {1, 0}, {1, 0.001}, {0.001, 0.001}, {0.001, 1}, {0, 1}});
  const PartGraph l = part_graph(thin_l.whole);
  CHECK(l.node_count() == 14);
  CHECK(graph_problem(thin_l.whole, l) == "");
  // The same L a thousand times thinner still: the same graph size.
  const GridFace thinner = test::grid_face_of({{0, 0}, {1, 0}, {1, 1e-6}, {1e-6, 1e-6}, {1e-6, 1}, {0, 1}});
  CHECK(part_graph(thinner.whole).node_count() == 14);
}

TEST_CASE("bounded graphs have at most three nodes per corner on thin-feature faces and their pieces", "[graph]") {
  // Faces drawn on a bounded grid, where features one unit wide are common (as in the issue-8
  // benchmarks), and the pieces random splitting makes of them.
  for (bool holes : {false, true}) {
    const GeneratorOptions options = thin_feature_options(11, 40, holes);
    std::vector<Part> parts = cut_pieces(8, holes ? 21 : 20, options);
    for (const GeneratedShape& s : test::generated_shapes(8, holes ? 23 : 22, options)) {
      parts.push_back(make_grid_face(s.polygon).whole);
    }
    int largest_ratio_hit = 0;
    for (const Part& part : parts) {
      const PartGraph g = part_graph(part);
      INFO("part with " << part.cell_count() << " cells, " << g.vertex_nodes.size() << " corners");
      REQUIRE(graph_problem(part, g) == "");
      CHECK(g.node_count() <= 3 * static_cast<int>(g.vertex_nodes.size()));
      largest_ratio_hit += g.node_count() > static_cast<int>(g.vertex_nodes.size());
    }
    CHECK(largest_ratio_hit > 0);  // edges do get split
  }
}
