// Mapped meshing of a general block model: shared nodes, conformal, exact affine elements.
#include "core/mesh/block_mesh.h"

#include <cmath>

#include <catch2/catch.hpp>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <random>

#include "core/data/general_generator.h"
#include "core/geometry/occt_face.h"
#include "core/io/input_face.h"
#include "core/mesh/edge_intervals.h"
#include "core/mesh/mesh_conformity.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/mesh/mesh_quality.h"
#include "core/mesh/mesh_smoothing.h"
#include "core/region/region_policy.h"
#include "support/mesh_fixtures.h"

using namespace autoblock;

namespace {
constexpr double kQ = 1e-7;

// A complete decomposition of face meshed at size through the pipeline, without the OpenCASCADE model.
MeshResult mesh_without_occt(const InputFace& face, const RegionDecomposition& d, double size) {
  REQUIRE(d.complete());
  MeshOptions options;
  options.size = size;
  options.occt_model = false;
  return mesh_region_decomposition(face, d, options);
}

}  // namespace

TEST_CASE("block mesh: a parallelogram block gives equal parallelograms of its angle", "[mesh][general]") {
  RegionDecomposition d;
  d.status = EpisodeStatus::Complete;
  FinishedRegion f;
  const double h = std::sqrt(3.0);
  f.region = Region(Ring{{0, 0}, {4, 0}, {5, h}, {1, h}}, {}, kQ);  // 60 degrees
  f.corners = *block_corners(f.region);
  d.finished.push_back(f);
  const BlockModel m = block_model(d, BlockRules{}, kQ);
  IntervalOptions options;
  options.target_size = 0.5;
  const IntervalAssignment a = assign_edge_intervals(m, options);
  const QuadMesh mesh = block_model_mesh(m, a.intervals, 0.0);
  CHECK(static_cast<long>(mesh.quads.size()) == a.quads);
  const MeshQuality q = mesh_quality(mesh);
  CHECK(q.min_scaled_jacobian == Approx(std::sin(M_PI / 3.0)));
  CHECK(q.mean_scaled_jacobian == Approx(std::sin(M_PI / 3.0)));
  CHECK(q.irregular_interior_nodes == 0);
  const Conformity c = check_conformity(mesh, std::vector<Ring>{f.region.outer()}, kModelToleranceQuanta * kQ);
  CHECK(c.conformal);
  CHECK(c.quad_area == Approx(4.0 * h));
}

TEST_CASE("block mesh: general decompositions with holes mesh conformally, templates included", "[mesh][general]") {
  // A square with a turned square hole, and a triangle: the greedy general engine's blocks and
  // templates, meshed; the independent check on the face's loops.
  const std::vector<std::pair<Ring, std::vector<Ring>>> faces = {
      {Ring{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {Ring{{5, 3}, {3, 5}, {5, 7}, {7, 5}}}},
      {Ring{{0, 0}, {8, 0}, {2, 7}}, {}},
      {Ring{{0, 0}, {9, 0}, {9, 2}, {6, 5}, {0, 5}}, {}}};
  for (const auto& [outer, holes] : faces) {
    const Region face(outer, holes, kQ);
    RegionGreedyPolicy greedy;
    const RegionDecomposition d = decompose_region(face, greedy);
    REQUIRE(d.complete());
    const BlockModel m = block_model(d, BlockRules{}, kQ);
    IntervalOptions options;
    options.target_size = 0.7;
    const IntervalAssignment a = assign_edge_intervals(m, options);
    const QuadMesh mesh = block_model_mesh(m, a.intervals, 0.0);
    const std::vector<Ring> loops = face.loops();
    const Conformity c = check_conformity(mesh, loops, kModelToleranceQuanta * kQ);
    INFO(c.problem);
    CHECK(c.conformal);
    CHECK(c.quad_area == Approx(face.area()));
    CHECK(mesh.blocks == static_cast<int>(d.finished.size()));
  }
}

TEST_CASE("block mesh: every generated general face meshes all-quad and conformal", "[mesh][general][property]") {
  // 1000 random polygons and chamfered unions, a third with holes, 5 to 20 vertices, at two scales;
  // the general engine's greedy policy with the mesh preset (deterministic; the search's time limit
  // is not), through the mesh pipeline (OpenCASCADE's replay and merge, intervals, mapped mesh,
  // smoothing, twisted parts refined). Every mesh must pass the independent check with the face's
  // area, and have no inverted quad.
  std::mt19937_64 rng(20261130);
  int faces = 0;
  for (int i = 0; i < 1000; ++i) {
    GeneralOptions options;
    options.kind = i % 3 == 2 ? GeneralKind::Chamfered : GeneralKind::Polygon;
    options.holes = i % 3 == 1;
    options.max_vertices = 20;
    options.size = i % 2 ? 100.0 : 0.37;
    const GeneralShape shape = generate_general_shape(rng, options);
    const InputFace face =
        input_face_from_occt(occt_face_from_polygon(RectilinearPolygon{shape.outer, shape.holes}, 0.0, true), "face");
    INFO("face " << i);
    if (!face.is_general()) continue;  // a chamfered union whose chamfers all merged away
    RegionGreedyPolicy greedy;
    RegionEpisodeOptions episode;
    episode.reward = RewardPreset::Mesh;  // the preset `autoblock mesh` decomposes with
    const RegionDecomposition d = decompose_region(face.region, greedy, episode);
    REQUIRE(d.complete());
    MeshOptions mesh_options;
    mesh_options.size = face.region.bbox().longer_side() / 15.0;
    mesh_options.general = episode;
    const MeshResult m = mesh_region_decomposition(face, d, mesh_options);
    INFO(m.conformity.problem);
    CHECK(m.conformity.conformal);
    CHECK(m.conformity.inverted_quads == 0);
    CHECK(m.conformity.quad_area == Approx(face.region.area()).epsilon(1e-6));
    faces += m.conformity.conformal;
  }
  CHECK(faces > 900);  // the rest are chamfered unions whose chamfers all merged away (rectilinear)
}

TEST_CASE("graded spacing from an edge's ends against hand values", "[mesh][block]") {
  auto check = [](const std::vector<double>& got, const std::vector<double>& want) {
    REQUIRE(got.size() == want.size());
    for (size_t k = 0; k < want.size(); ++k) CHECK(got[k] == Approx(want[k]).margin(1e-12));
  };
  // No limit, or limits no shorter than the uniform interval: uniform.
  check(graded_fractions(4, 10.0, 0.0, 0.0, 2.0), {0.0, 0.25, 0.5, 0.75, 1.0});
  check(graded_fractions(4, 10.0, 2.5, 3.0, 2.0), {0.0, 0.25, 0.5, 0.75, 1.0});
  check(graded_fractions(1, 10.0, 0.1, 0.1, 2.0), {0.0, 1.0});
  // From the start: 1, 2, then capped at the size that fills 10 (1 + 2 + 2 s = 10: 3.5, 3.5).
  check(graded_fractions(4, 10.0, 1.0, 0.0, 2.0), {0.0, 0.1, 0.3, 0.65, 1.0});
  // From the end, the same mirrored.
  check(graded_fractions(4, 10.0, 0.0, 1.0, 2.0), {0.0, 0.35, 0.7, 0.9, 1.0});
  // From both ends: 1, 2, 4, 2, 1 fill 10 exactly.
  check(graded_fractions(5, 10.0, 1.0, 1.0, 2.0), {0.0, 0.1, 0.3, 0.7, 0.9, 1.0});
  // Too few intervals to fill 10 from a first of 1 at ratio 2 (1 + 2 + 4 = 7): all scaled by 10 / 7.
  check(graded_fractions(3, 10.0, 1.0, 0.0, 2.0), {0.0, 1.0 / 7.0, 3.0 / 7.0, 1.0});
}

TEST_CASE("block mesh: a T-junction the first block model misses is meshed with the wide tolerance", "[mesh][block_model]") {
  // A 2 x 2 square: a long block below, two squares above whose shared corner lies 7 quanta above the
  // long block's top side (block_model_test: imprinted at the wide tolerance, not at the first). The
  // first model's mesh has hanging nodes there and fails its check; the mesh kept is the wide model's,
  // conformal.
  InputFace face;
  face.region = Region(Ring{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}, kQ);
  RegionDecomposition d;
  d.status = EpisodeStatus::Complete;
  const double y = 1.0 + 7.0 * kQ;
  auto part = [](int id, const Ring& ring) { return test::finished_block(id, ring, kQ); };
  d.finished.push_back(part(0, Ring{{0, 0}, {2, 0}, {2, 1}, {0, 1}}));
  d.finished.push_back(part(1, Ring{{0, 1}, {1, y}, {1, 2}, {0, 2}}));
  d.finished.push_back(part(2, Ring{{1, y}, {2, 1}, {2, 2}, {1, 2}}));
  const MeshResult m = mesh_without_occt(face, d, 0.25);
  INFO(m.conformity.problem);
  CHECK(m.wide_tolerance);
  CHECK(m.conformity.conformal);
  CHECK(m.conformity.quad_area == Approx(4.0));
}

TEST_CASE("block mesh: a vertex between two edges in line is a node of the mesh", "[mesh][block_model]") {
  // A pentagon whose bottom edge is two edges meeting at (3.37, 0), and a quadrilateral with a hole
  // whose bottom edge is three edges and whose hole has such a vertex too: the region merges them, the
  // block model imprints each into the side it lies on, the smoothing does not slide it away (its
  // neighbours are in line with it), and the mesh has a node there (on the face's lattice, as every
  // vertex's node is).
  using Loop = std::vector<std::pair<double, double>>;
  auto wire_of = [](const Loop& loop) {
    BRepBuilderAPI_MakePolygon wire;
    for (const auto& [x, y] : loop) wire.Add(gp_Pnt(x, y, 0));
    wire.Close();
    return wire.Wire();
  };
  const std::vector<std::pair<Loop, Loop>> faces = {
      {{{0, 0}, {3.37, 0}, {10, 0}, {12, 5}, {1, 4}}, {}},
      {{{0, 0}, {2.2, 0}, {5.1, 0}, {10, 0}, {11, 6}, {0, 6}}, {{3, 2}, {3, 4}, {7, 4}, {7, 2.7}, {5, 2.35}}}};
  for (const auto& [outer, hole] : faces) {
    BRepBuilderAPI_MakeFace make(wire_of(outer));
    if (!hole.empty()) make.Add(wire_of(hole));
    const InputFace face = input_face_from_occt(make.Face(), "split edges");
    REQUIRE(face.is_general());
    const size_t merged = hole.empty() ? 1 : 3;
    CHECK(face.region.vertex_count() == static_cast<int>(outer.size() + hole.size() - merged));
    REQUIRE(face.straight_vertices.size() == merged);
    RegionGreedyPolicy greedy;
    const RegionDecomposition d = decompose_region(face.region, greedy);
    const MeshResult m = mesh_without_occt(face, d, hole.empty() ? 1.0 : 0.55);
    INFO(m.conformity.problem);
    CHECK(m.conformity.conformal);
    const double q = face.region.quantum();
    for (const Point2& v : face.straight_vertices) {
      double nearest = 1e300;
      for (const Point2& n : m.mesh.nodes) nearest = std::min(nearest, std::hypot(n.x - v.x, n.y - v.y));
      INFO(v.x << ", " << v.y);
      CHECK(nearest <= q);
    }
    // Without them the block model has no vertex there.
    const BlockModel plain = block_model(d, d.rules, q);
    for (const Point2& v : face.straight_vertices) {
      CHECK(std::none_of(plain.vertices.begin(), plain.vertices.end(), [&](Point2 p) { return std::hypot(p.x - v.x, p.y - v.y) < 1e-3; }));
    }
  }
}
