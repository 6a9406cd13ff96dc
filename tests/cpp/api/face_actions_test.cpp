// The front ends' entry points: policy catalogue, checking, decomposing, stepping.
#include "support/catch_torch.h"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "core/api/face_actions.h"
#include "core/api/training_job.h"
#include "core/io/text_file.h"
#include "core/mesh/mesh_export.h"
#include "core/sac/policy_file.h"
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

TEST_CASE("face_vertex_scores: a learned policy scores every vertex of the step's part", "[api]") {
  const InputFace face = l_face();
  DecomposeSettings settings;
  settings.policy = "sac-mesh";
  const FaceDecomposition result = decompose_input_face(face, settings);
  const auto cuts = cut_specs(result.decomposition.cuts);
  REQUIRE_FALSE(cuts.empty());
  const EpisodeSnapshot first = face_step(face, cuts, 0, 0, result.decomposition.reward);
  const std::vector<double> scores = face_vertex_scores(face, cuts, 0, "sac-mesh", 0, result.decomposition.reward);
  REQUIRE(scores.size() == first.vertices.size());
  // A vertex through which no candidate cut runs (its lines only follow the boundary) scores -infinity.
  const auto finite = std::count_if(scores.begin(), scores.end(), [](double s) { return std::isfinite(s); });
  CHECK(finite >= 2);
  for (double s : scores) CHECK((std::isfinite(s) || s == -std::numeric_limits<double>::infinity()));
  // The deployed policy cuts at a vertex with the best score.
  CHECK(scores[static_cast<size_t>(first.chosen_vertex)] == Approx(*std::max_element(scores.begin(), scores.end())));
  CHECK_THROWS_WITH(face_vertex_scores(face, cuts, 0, "greedy"), Catch::Contains("baseline"));
  CHECK_THROWS_WITH(face_vertex_scores(face, cuts, static_cast<int>(cuts.size()), "sac-mesh"),
                    Catch::Contains("no cut follows"));
}

TEST_CASE("face_mesh meshes a decomposition from its cut sequence", "[api]") {
  const InputFace face = l_face();
  DecomposeSettings settings;
  settings.policy = "optimal";
  const FaceDecomposition result = decompose_input_face(face, settings);
  const auto cuts = cut_specs(result.decomposition.cuts);
  MeshOptions options;
  options.size = 0.25;
  const FaceMesh mesh = face_mesh(face, cuts, 0, result.decomposition.reward, options);
  CHECK(mesh.decomposition.blocks.size() == result.decomposition.blocks.size());
  CHECK(mesh.result.conformity.conformal);
  CHECK(mesh.result.mesh.blocks == 2);
  CHECK(mesh.result.mesh.quads.size() == 48);  // the L of area 3 in quads of 0.25 x 0.25
  CHECK(mesh.result.mesh.z == 2.0);
  const std::vector<CutSpec> foreign{{0, Point2{7, 7}, CutDirection::Vertical}};
  CHECK_THROWS_AS(face_mesh(face, foreign, 0, RewardPreset::Paper, options), InputError);
  options.size = -1;
  CHECK_THROWS_AS(face_mesh(face, cuts, 0, result.decomposition.reward, options), InputError);
}

TEST_CASE("run_training_job trains, stops, resumes and writes the policy", "[api][training]") {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / "autoblock-training-job-test";
  fs::remove_all(folder);
  fs::create_directories(folder);
  TrainingJob job;
  job.output = (folder / "policy.pt").string();
  job.train_generate.count = 3;
  job.train_generate.seed = 1;
  job.train_generate.options.max_rects = 4;
  job.test_generate.count = 2;
  job.test_generate.seed = 2;
  job.test_generate.options.max_rects = 4;
  job.episodes = 6;
  job.eval_every = 2;
  job.reward = "mesh";
  std::vector<int> seen;
  int tests = 0;
  TrainingCallbacks callbacks;
  callbacks.on_episode = [&](const EpisodeRecord& r, bool earlier) {
    if (!earlier) seen.push_back(r.episode);
    tests += r.evaluated;
  };
  callbacks.should_stop = [&] { return seen.size() == 3; };
  const TrainingOutcome stopped = run_training_job(job, callbacks);
  CHECK(stopped.cancelled);
  CHECK(stopped.episodes_done == 3);
  CHECK(stopped.policy_file.empty());
  CHECK(stopped.reward == "mesh");
  CHECK(fs::exists(stopped.checkpoint));
  CHECK(fs::exists(stopped.log));
  CHECK_FALSE(fs::exists(job.output));

  job.resume = true;
  int earlier = 0;
  seen.clear();
  callbacks.on_episode = [&](const EpisodeRecord& r, bool before) {
    if (before) ++earlier; else seen.push_back(r.episode);
  };
  callbacks.should_stop = {};
  const TrainingOutcome done = run_training_job(job, callbacks);
  CHECK(earlier == 3);
  CHECK(seen == std::vector<int>{4, 5, 6});
  CHECK_FALSE(done.cancelled);
  CHECK(done.policy_file == job.output);
  CHECK(fs::exists(done.curves));
  CHECK(load_policy_file(job.output, false).agent->config().reward == RewardPreset::Mesh);
  // The policy decomposes faces like a shipped one.
  DecomposeSettings trained;
  trained.policy = job.output;
  CHECK(decompose_input_face(l_face(), trained).decomposition.complete());

  TrainingJob bad = job;
  bad.output = (folder / "missing" / "p.pt").string();
  CHECK_THROWS_WITH(run_training_job(bad, {}), Catch::Contains("does not exist"));
  bad = job;
  bad.resume = false;
  bad.reward = "nope";
  CHECK_THROWS_AS(run_training_job(bad, {}), InputError);
  bad = job;
  bad.resume = false;
  bad.train_generate.count = 0;
  bad.train_folder = (folder / "none").string();
  CHECK_THROWS_AS(run_training_job(bad, {}), InputError);
  fs::remove_all(folder);
}
