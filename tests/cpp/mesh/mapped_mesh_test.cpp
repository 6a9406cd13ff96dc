// Mapped meshing: conformal meshes of exact rectangles, hand-made T-junctions, hundreds of faces.
#include <catch2/catch.hpp>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/geometry/occt_face.h"
#include "core/io/input_face.h"
#include "core/mesh/mesh_conformity.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/mesh/mesh_quality.h"
#include "support/mesh_fixtures.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {

// Valence (quads around it) of the node at p.
int valence_at(const QuadMesh& mesh, Point2 p) {
  int node = -1;
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (mesh.nodes[n] == p) {
      REQUIRE(node < 0);  // one node per position: shared, not duplicated
      node = static_cast<int>(n);
    }
  }
  REQUIRE(node >= 0);
  int valence = 0;
  for (const auto& q : mesh.quads) valence += std::count(q.begin(), q.end(), node);
  return valence;
}

void check_perfect(const QuadMesh& mesh, const RectilinearPolygon& polygon) {
  const Conformity c = check_conformity(mesh, polygon);
  INFO(c.problem);
  CHECK(c.conformal);
  CHECK(c.quad_area == Approx(polygon_area(polygon)).epsilon(1e-12));
  const MeshQuality q = mesh_quality(mesh);
  CHECK(q.min_scaled_jacobian == 1.0);  // exactly
  CHECK(q.irregular_interior_nodes == 0);
  CHECK(q.max_skew == 0.0);
}

// A rectangular face's mesh at size: the exact search's one block, meshed.
MeshResult one_block_mesh(const InputFace& face, double size) {
  auto policy = make_baseline_policy("optimal", face.grid.size, BaselineOptions{});
  const Decomposition d = decompose_face(face.grid, *policy);
  REQUIRE(d.blocks.size() == 1);
  MeshOptions options;
  options.size = size;
  return mesh_decomposition(face, d, options);
}

}  // namespace

TEST_CASE("pinwheel: every T-junction's mesh line crosses the neighbour", "[mesh][mapped]") {
  const test::HandModel m = test::hand_model(test::square3(), {}, test::pinwheel_blocks());
  IntervalOptions options;
  options.target_size = 0.5;
  const IntervalAssignment a = assign_intervals(m.layout, options);
  const QuadMesh mesh = test::hand_mesh(m, a);
  check_perfect(mesh, m.face.planar.polygon);
  CHECK(mesh.quads.size() == 36);  // 6 x 6 squares of 0.5
  CHECK(mesh.nodes.size() == 49);
  // The centre square's corners are T-junctions of the blocks; in the mesh they are regular.
  for (Point2 p : {Point2{1, 1}, Point2{2, 1}, Point2{2, 2}, Point2{1, 2}}) CHECK(valence_at(mesh, p) == 4);
  std::map<int, int> per_block;
  for (int b : mesh.quad_block) ++per_block[b];
  CHECK(per_block == std::map<int, int>{{0, 8}, {1, 8}, {2, 8}, {3, 8}, {4, 4}});
}

TEST_CASE("T-junction with uneven sides: opposite sides carry nodes at the same positions", "[mesh][mapped]") {
  // Lower block [0,5] x [0,1]; above it [0,1] and [1,5]; h = 0.7 gives the strips of length 1 and
  // 4 two and six intervals (sizes 0.5 and 0.667): the lower block's top and bottom both have 8
  // intervals, with x = 1 on both.
  const test::HandModel m =
      test::hand_model({{0, 0}, {5, 0}, {5, 2}, {0, 2}}, {}, {Box{0, 0, 5, 1}, Box{0, 1, 1, 2}, Box{1, 1, 5, 2}});
  IntervalOptions options;
  options.target_size = 0.7;
  const QuadMesh mesh = test::hand_mesh(m, assign_intervals(m.layout, options));
  check_perfect(mesh, m.face.planar.polygon);
  CHECK(valence_at(mesh, Point2{1, 0}) == 2);  // the T-junction's line reaches the bottom
  CHECK(valence_at(mesh, Point2{1, 1}) == 4);
  std::vector<double> bottom, top;
  for (const Point2& p : mesh.nodes) {
    if (p.y == 0) bottom.push_back(p.x);
    if (p.y == 1) top.push_back(p.x);
  }
  std::sort(bottom.begin(), bottom.end());
  std::sort(top.begin(), top.end());
  CHECK(bottom.size() == 9);
  CHECK(bottom == top);
}

TEST_CASE("hand-made faces with holes and nested T-junctions mesh perfectly", "[mesh][mapped]") {
  // A square with a hole, blocks in a pinwheel around it.
  const test::HandModel ring = test::hand_model(test::square3(), {test::centre_hole()},
                                                {Box{0, 0, 2, 1}, Box{2, 0, 3, 2}, Box{1, 2, 3, 3}, Box{0, 1, 1, 3}});
  for (double h : {0.3, 1.0, 5.0}) {
    IntervalOptions options;
    options.target_size = h;
    check_perfect(test::hand_mesh(ring, assign_intervals(ring.layout, options)), ring.face.planar.polygon);
  }
  // Staircase of T-junctions: block corners at x = 1, 2, 3 on different rows.
  const test::HandModel stairs = test::hand_model(
      {{0, 0}, {4, 0}, {4, 3}, {0, 3}}, {},
      {Box{0, 0, 1, 1}, Box{1, 0, 4, 1}, Box{0, 1, 2, 2}, Box{2, 1, 4, 2}, Box{0, 2, 3, 3}, Box{3, 2, 4, 3}});
  IntervalOptions options;
  options.target_size = 0.45;
  const QuadMesh mesh = test::hand_mesh(stairs, assign_intervals(stairs.layout, options));
  check_perfect(mesh, stairs.face.planar.polygon);
  for (Point2 p : {Point2{1, 1}, Point2{2, 1}, Point2{1, 2}, Point2{2, 2}, Point2{3, 1}, Point2{3, 2}}) {
    CHECK(valence_at(mesh, p) == 4);
  }
}

TEST_CASE("the conformity check catches hanging nodes, gaps and overlaps", "[mesh][conformity]") {
  const RectilinearPolygon face = test::polygon_of({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  QuadMesh good;
  good.nodes = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
  good.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  good.quad_block = {0, 1};
  good.blocks = 2;
  CHECK(check_conformity(good, face).conformal);
  QuadMesh hanging = good;  // the left quad split in two: (1, 0.5) hangs on the right quad's side
  hanging.nodes.push_back({0, 0.5});
  hanging.nodes.push_back({1, 0.5});
  hanging.quads = {{0, 1, 7, 6}, {6, 7, 4, 3}, {1, 2, 5, 4}};
  hanging.quad_block = {0, 0, 1};
  const Conformity h = check_conformity(hanging, face);
  CHECK_FALSE(h.conformal);
  CHECK(h.stray_boundary_edges == 3);  // two halves on the left, the whole side on the right
  QuadMesh duplicated = good;  // the right quad on its own copies of the shared nodes
  duplicated.nodes.push_back({1, 0});
  duplicated.nodes.push_back({1, 1});
  duplicated.quads[1] = {6, 2, 5, 7};
  CHECK_FALSE(check_conformity(duplicated, face).conformal);
  QuadMesh gap = good;
  gap.quads.pop_back();
  CHECK_FALSE(check_conformity(gap, face).conformal);
  QuadMesh inverted = good;
  inverted.quads[0] = {0, 3, 4, 1};
  const Conformity i = check_conformity(inverted, face);
  CHECK_FALSE(i.conformal);
  CHECK(i.misoriented_edges == 1);  // the shared edge runs the same way in both quads
  CHECK(i.inverted_quads == 1);
  // A quad with a reflex corner (positive area, a negative Jacobian at one corner) is inverted too:
  // the shared node (1, 1) pulled into the left quad past its diagonal.
  QuadMesh dart = good;
  dart.nodes[4] = {0.3, 0.2};
  const Conformity d = check_conformity(dart, face);
  CHECK_FALSE(d.conformal);
  CHECK(d.inverted_quads == 1);
  CHECK(d.first_inverted.x == Approx(0.325));  // the left quad's centre
  CHECK(d.first_inverted.y == Approx(0.3));
  // One quad over the whole face, clockwise: inverted and nothing else, and the verdict says where.
  QuadMesh clockwise;
  clockwise.nodes = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  clockwise.quads = {{0, 3, 2, 1}};
  clockwise.quad_block = {0};
  clockwise.blocks = 1;
  const Conformity w = check_conformity(clockwise, face);
  CHECK(w.problem == "1 quad is inverted or degenerate (the first near 1, 0.5)");
}

TEST_CASE("autoblock meshes hundreds of generated faces conformally with perfect quads", "[mesh][mapped][occt]") {
  int meshed = 0, with_t_junctions = 0;
  for (bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    const auto shapes = test::generated_shapes(100, holes ? 91 : 90, options);
    for (size_t s = 0; s < shapes.size(); ++s) {
      const InputFace face = input_face_from_occt(occt_face_from_polygon(shapes[s].polygon, -2.0, s % 2 == 1), "generated");
      const std::string policy_name = s % 2 ? "greedy" : "optimal";
      auto policy = make_baseline_policy(policy_name, face.grid.size, BaselineOptions{});
      const Decomposition d = decompose_face(face.grid, *policy);
      MeshOptions mesh_options;
      mesh_options.size = (s % 3 == 0 ? 0.0 : 0.6 + 0.1 * static_cast<double>(s % 7));
      const MeshResult r = mesh_decomposition(face, d, mesh_options);
      INFO("shape " << s << " holes " << holes << " policy " << policy_name << ": " << r.conformity.problem);
      CHECK(r.conformity.conformal);
      CHECK(r.conformity.quad_area == Approx(polygon_area(face.planar.polygon)).epsilon(1e-12));
      CHECK(r.quality.min_scaled_jacobian == 1.0);
      CHECK(r.quality.irregular_interior_nodes == 0);
      CHECK(r.mesh.quads.size() == static_cast<size_t>(r.intervals.quads));
      CHECK(r.mesh.z == -2.0);
      CHECK(r.mesh.blocks == static_cast<int>(d.blocks.size()));
      // A T-junction: a block corner strictly inside another block's side.
      bool t_junction = false;
      for (const Box& a : d.blocks) {
        for (const Box& b : d.blocks) {
          for (Point2 p : {Point2{a.xmin, a.ymin}, Point2{a.xmax, a.ymin}, Point2{a.xmin, a.ymax}, Point2{a.xmax, a.ymax}}) {
            const bool on_horizontal = (p.y == b.ymin || p.y == b.ymax) && p.x > b.xmin && p.x < b.xmax;
            const bool on_vertical = (p.x == b.xmin || p.x == b.xmax) && p.y > b.ymin && p.y < b.ymax;
            t_junction = t_junction || on_horizontal || on_vertical;
          }
        }
      }
      with_t_junctions += t_junction;
      ++meshed;
    }
  }
  CHECK(meshed == 200);
  CHECK(with_t_junctions > 50);  // the cases that matter are well represented
}

TEST_CASE("a rectangular face is one block and one structured grid", "[mesh][mapped]") {
  const InputFace face =
      input_face_from_occt(occt_face_from_polygon(test::polygon_of({{0, 0}, {3, 0}, {3, 2}, {0, 2}}), 1, false), "rect");
  const MeshResult r = one_block_mesh(face, 0.5);
  CHECK(r.mesh.quads.size() == 24);
  CHECK(r.mesh.nodes.size() == 35);
  check_perfect(r.mesh, face.planar.polygon);
}

TEST_CASE("a vertex between two edges in line is a mesh node, its line run across the face", "[mesh][mapped]") {
  // A 10 x 4 rectangle whose bottom edge is two edges meeting at (3.37, 0) and whose left edge is two
  // meeting at (0, 2.71) (as a solid's face is split where a neighbour's edge ends): the polygon
  // merges them, the mesh keeps a node at each, and the mesh lines through them cross the face.
  BRepBuilderAPI_MakePolygon wire;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {3.37, 0}, {10, 0}, {10, 4}, {0, 4}, {0, 2.71}}) {
    wire.Add(gp_Pnt(x, y, 0));
  }
  wire.Close();
  const InputFace face = input_face_from_occt(BRepBuilderAPI_MakeFace(wire.Wire()).Face(), "split rectangle");
  REQUIRE_FALSE(face.is_general());
  CHECK(face.planar.polygon.outer.size() == 4);
  REQUIRE(face.straight_vertices.size() == 2);
  const MeshResult r = one_block_mesh(face, 1.0);
  check_perfect(r.mesh, face.planar.polygon);
  auto has_node = [&](Point2 p) {
    return std::any_of(r.mesh.nodes.begin(), r.mesh.nodes.end(),
                       [&](Point2 n) { return std::fabs(n.x - p.x) < 1e-12 && std::fabs(n.y - p.y) < 1e-12; });
  };
  for (const Point2 p : {Point2{3.37, 0}, Point2{3.37, 4}, Point2{0, 2.71}, Point2{10, 2.71}}) {
    INFO(p.x << ", " << p.y);
    CHECK(has_node(p));
  }
}

TEST_CASE("meshing refuses incomplete decompositions", "[mesh][errors]") {
  const InputFace face = input_face_from_occt(occt_face_from_polygon(test::polygon_of(test::l_shape()), 0, true), "L");
  auto policy = make_baseline_policy("random", face.grid.size, BaselineOptions{});
  EpisodeOptions capped;
  capped.max_steps = 1;
  Decomposition d = decompose_face(face.grid, *policy, capped);
  d.status = EpisodeStatus::Truncated;  // whatever the random cut did, pretend it stopped early
  MeshOptions options;
  options.episode = capped;
  CHECK_THROWS_WITH(mesh_decomposition(face, d, options), Contains("incomplete"));
}
