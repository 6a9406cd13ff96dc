// The front ends' entry points: policy catalogue, checking, decomposing, stepping.
#include "support/catch_torch.h"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>

#include "core/api/face_actions.h"
#include "core/common/error.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "support/bad_shapes.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

int face_count(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return faces.Extent();
}

InputFace l_face() {
  return check_face(occt_face_from_polygon(test::polygon_of(test::l_shape()), 2.0, true), "L");
}

}  // namespace

TEST_CASE("the catalogue lists policies every front end can make", "[api]") {
  const InputFace face = l_face();
  const auto names = policy_names();
  REQUIRE_FALSE(names.empty());
  CHECK(std::find(names.begin(), names.end(), default_policy_name()) != names.end());
  for (const std::string& name : names) CHECK(policy_source(name, {})->make(face.grid.size, 0) != nullptr);
  CHECK_NOTHROW(check_reward_preset(default_reward_preset()));
  CHECK_NOTHROW(check_reward_preset("mesh"));
  CHECK_THROWS_AS(check_reward_preset("nope"), InputError);
  CHECK_THROWS_WITH(policy_source("nope", {}), Catch::Contains("unknown policy 'nope'"));
  CHECK_THROWS_WITH(policy_source("/tmp/no-such-policy.pt", {}), Catch::Contains("unknown policy"));
}

TEST_CASE("decompose_input_face gives the blocks as faces and a compound", "[api]") {
  const InputFace face = l_face();
  const FaceDecomposition result = decompose_input_face(face, DecomposeSettings{});
  CHECK(result.decomposition.policy == default_policy_name());
  CHECK(result.decomposition.complete());
  REQUIRE(result.block_faces.size() == result.decomposition.blocks.size());
  CHECK(result.block_faces.size() == 2);
  CHECK(face_count(result.shape) == 2);
  CHECK(occt_area(result.shape) == Approx(3.0));
  CHECK(occt_shape_valid(result.shape));

  DecomposeSettings bad;
  bad.policy = "nope";
  CHECK_THROWS_AS(decompose_input_face(face, bad), InputError);
  bad = DecomposeSettings{};
  bad.reward = "nope";
  CHECK_THROWS_AS(decompose_input_face(face, bad), InputError);
}

TEST_CASE("face_step replays a decomposition's cuts", "[api]") {
  const InputFace face = l_face();
  const FaceDecomposition result = decompose_input_face(face, DecomposeSettings{});
  const auto cuts = cut_specs(result.decomposition.cuts);
  const EpisodeSnapshot last = face_step(face, cuts, static_cast<int>(cuts.size()), 0, result.decomposition.reward);
  CHECK(last.blocks == static_cast<int>(result.decomposition.blocks.size()));
  CHECK(last.return_so_far == Approx(result.decomposition.total_return));
}

TEST_CASE("check_face rejects unsupported faces with InputError", "[api]") {
  int checked = 0;
  for (const test::BadShape& bad : test::bad_shapes()) {
    if (bad.shape.IsNull() || bad.shape.ShapeType() != TopAbs_FACE) continue;
    INFO(bad.name);
    CHECK_THROWS_WITH(check_face(TopoDS::Face(bad.shape), "bad"), Catch::Contains(bad.expected));
    ++checked;
  }
  CHECK(checked >= 5);
}
