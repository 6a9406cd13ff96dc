// The conformal merge: shared edges (IsSame), imprinted T-junctions, union equal to the face.
#include <catch2/catch.hpp>

#include <BRepAlgoAPI_Cut.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "core/baselines/baseline_policy.h"
#include "core/env/decomposition.h"
#include "core/env/occt_replay.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/io/shape_file.h"
#include "core/mesh/conformal_merge.h"
#include "support/mesh_fixtures.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

int vertex_count(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  return vertices.Extent();
}

// The part of `face` the compound does not cover.
double uncovered_area(const TopoDS_Face& face, const TopoDS_Shape& compound) {
  BRepAlgoAPI_Cut cut(face, compound);
  REQUIRE(cut.IsDone());
  return occt_area(cut.Shape());
}

}  // namespace

TEST_CASE("conformal merge of a pinwheel imprints every T-junction", "[mesh][merge]") {
  const test::HandModel m = test::hand_model(test::square3(), {}, test::pinwheel_blocks());
  REQUIRE(m.model.faces.size() == 5);
  test::check_conformal_model(m.model, m.face.planar.polygon);
  // Each outer block carries the T-junction of the centre square on its long side.
  for (size_t b = 0; b < 4; ++b) CHECK(vertex_count(m.model.faces[b]) == 5);
  CHECK(vertex_count(m.model.faces[4]) == 4);
  CHECK(vertex_count(m.model.compound) == 12);
  CHECK(uncovered_area(m.face.occt, m.model.compound) == Approx(0).margin(1e-9));
}

TEST_CASE("conformal merge around a hole keeps the hole", "[mesh][merge]") {
  // [0,3]^2 minus [1,2]^2, as four blocks with T-junctions at the hole's corners.
  const std::vector<Box> blocks{{0, 0, 2, 1}, {2, 0, 3, 2}, {1, 2, 3, 3}, {0, 1, 1, 3}};
  const test::HandModel m = test::hand_model(test::square3(), {test::centre_hole()}, blocks);
  test::check_conformal_model(m.model, m.face.planar.polygon);
  CHECK(occt_area(m.model.compound) == Approx(8.0));
  CHECK(uncovered_area(m.face.occt, m.model.compound) == Approx(0).margin(1e-9));
}

TEST_CASE("conformal merge of replayed decompositions: shared edges, union equals the face", "[mesh][merge][occt]") {
  for (bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    const auto shapes = test::generated_shapes(60, holes ? 71 : 70, options);
    for (size_t s = 0; s < shapes.size(); ++s) {
      const InputFace face = input_face_from_occt(occt_face_from_polygon(shapes[s].polygon, 1.5, s % 2 == 0), "generated");
      auto policy = make_baseline_policy(s % 3 == 0 ? "greedy" : "optimal", face.grid.size, BaselineOptions{});
      const Decomposition d = decompose_face(face.grid, *policy);
      INFO("shape " << s << " holes " << holes);
      const ConformalBlocks model = conformal_merge(replay_cuts_occt(face.occt, face.grid, d.cuts));
      REQUIRE(model.faces.size() == d.blocks.size());
      test::check_conformal_model(model, face.planar.polygon);
      CHECK(uncovered_area(face.occt, model.compound) == Approx(0).margin(1e-9 * face.grid.size * face.grid.size));
      if (s % 10 == 0) {  // sharing survives a BREP round trip
        const TopoDS_Shape back = read_brep_text(write_brep_text(model.compound));
        CHECK(vertex_count(back) == vertex_count(model.compound));
        TopTools_IndexedMapOfShape a, b;
        TopExp::MapShapes(model.compound, TopAbs_EDGE, a);
        TopExp::MapShapes(back, TopAbs_EDGE, b);
        CHECK(a.Extent() == b.Extent());
      }
    }
  }
}
