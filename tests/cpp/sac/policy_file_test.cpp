#include "support/catch_torch.h"

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/region/region_episode.h"
#include "core/region/region_policy.h"
#include "core/sac/policy_file.h"
#include "core/api/policy_source.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

TEST_CASE("a policy file round-trips either agent exactly", "[sac][policy]") {
  for (const std::string kind : {"paper", "lookahead"}) {
    INFO(kind);
    torch::manual_seed(11);
    SacConfig config = default_sac_config(kind);
    config.reward = RewardPreset::Mesh;
    auto agent = make_learning_agent(config);
    const std::string path = test::temporary_folder("policy") + "/p.pt";
    save_policy_file(path, *agent, {{"note", "test"}}, false);
    const LoadedPolicy loaded = load_policy_file(path, false);
    CHECK(loaded.meta["kind"] == "policy");
    CHECK(loaded.meta["training"]["note"] == "test");
    CHECK(loaded.agent->config().reward == RewardPreset::Mesh);
    CHECK(loaded.agent->config().agent == kind);
    GeneratorOptions options;
    options.holes = true;
    for (const GeneratedShape& shape : test::generated_shapes(3, 8, options)) {
      const GridFace face = make_grid_face(shape.polygon);
      Episode episode(face);
      CHECK((loaded.agent->vertex_scores(episode) == agent->vertex_scores(episode)));
      auto a = agent->deployed_policy("a");
      auto b = loaded.agent->deployed_policy("b");
      CHECK(decompose_face(face, *a).total_return == decompose_face(face, *b).total_return);
    }
    CHECK_THROWS_WITH(load_policy_file(path, true), Contains("not a training checkpoint"));
  }
}

TEST_CASE("a policy file with two networks: the first decides on rectilinear faces, the second on general ones",
          "[sac][policy][general]") {
  SacConfig config = default_sac_config("lookahead");
  config.reward = RewardPreset::Mesh;
  torch::manual_seed(21);
  auto grid = make_learning_agent(config);
  torch::manual_seed(22);
  auto general = make_learning_agent(config);
  const std::string folder = test::temporary_folder("two-networks");
  save_policy_file(folder + "/grid.pt", *grid, {{"train", "grid faces"}}, false);
  save_policy_file(folder + "/general.pt", *general, {{"train", "general faces"}}, false);
  const nlohmann::json meta = combine_policy_files(folder + "/grid.pt", folder + "/general.pt", folder + "/both.pt");
  CHECK(meta["version"] == 2);
  CHECK(meta["training"]["train"] == "grid faces");
  CHECK(meta["general"]["training"]["train"] == "general faces");
  const LoadedPolicy both = load_policy_file(folder + "/both.pt", false);
  REQUIRE(both.general);
  CHECK(both.general_agent() == both.general);
  // Rectilinear faces: the first network's scores and decompositions.
  for (const GeneratedShape& shape : test::generated_shapes(3, 6, GeneratorOptions{})) {
    const GridFace face = make_grid_face(shape.polygon);
    Episode episode(face);
    CHECK((both.agent->vertex_scores(episode) == grid->vertex_scores(episode)));
  }
  // General faces: the second network's, which differ from the first's.
  const auto lock = lock_general_engine();
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  int differ = 0;
  for (int i = 0; i < 3; ++i) {
    const Region face = test::region_of(test::general_polygon(60 + i, GeneralKind::Polygon, i == 2));
    RegionEpisode episode(face, options);
    const std::vector<float> scores = both.general_agent()->region_vertex_scores(episode);
    CHECK((scores == general->region_vertex_scores(episode)));
    differ += scores != grid->region_vertex_scores(episode);
    auto a = general->deployed_region_policy("a");
    auto b = both.general_agent()->deployed_region_policy("b");
    CHECK(decompose_region(face, *a, options).total_return == decompose_region(face, *b, options).total_return);
  }
  CHECK(differ == 3);
  // Through the policy source, as every front end loads it.
  const PolicySource source(folder + "/both.pt");
  REQUIRE(source.learned());
  CHECK(source.learned_policy()->general_network());
  CHECK_FALSE(PolicySource(folder + "/grid.pt").learned_policy()->general_network());
  // Combining again takes each file's network for its kind: the general one of a two-network file.
  combine_policy_files(folder + "/both.pt", folder + "/both.pt", folder + "/again.pt");
  const LoadedPolicy again = load_policy_file(folder + "/again.pt", false);
  RegionEpisode episode(test::region_of(test::general_polygon(70, GeneralKind::Polygon, false)), options);
  CHECK((again.general_agent()->region_vertex_scores(episode) == general->region_vertex_scores(episode)));
  // Refused: a checkpoint of two networks, different presets, a general network without a policy.
  CHECK_THROWS_WITH(load_policy_file(folder + "/both.pt", true), Contains("not a training checkpoint"));
  SacConfig paper_reward = config;
  paper_reward.reward = RewardPreset::Paper;
  save_policy_file(folder + "/paper-reward.pt", *make_learning_agent(paper_reward), {}, false);
  CHECK_THROWS_WITH(combine_policy_files(folder + "/grid.pt", folder + "/paper-reward.pt", folder + "/x.pt"),
                    Contains("different reward presets"));
  // sac-faithful (paper preset) was written before the paper's agent learned on general faces.
  CHECK_THROWS_WITH(combine_policy_files(folder + "/paper-reward.pt", policy_file_path("sac-faithful"), folder + "/x.pt"),
                    Contains("has no policy on them"));
  CHECK_FALSE(std::filesystem::exists(folder + "/x.pt"));
}

TEST_CASE("missing, corrupt, truncated and foreign policy files are clear errors", "[sac][policy][errors]") {
  const std::string folder = test::temporary_folder("bad-policy");
  CHECK_THROWS_WITH(load_policy_file(folder + "/none.pt", false), Contains("no such policy file"));
  std::ofstream(folder + "/garbage.pt") << "this is not a policy";
  CHECK_THROWS_WITH(load_policy_file(folder + "/garbage.pt", false), Contains("corrupt or truncated"));
  torch::manual_seed(1);
  save_policy_file(folder + "/good.pt", *make_learning_agent(SacConfig{}), {}, false);
  const auto size = std::filesystem::file_size(folder + "/good.pt");
  std::filesystem::copy_file(folder + "/good.pt", folder + "/cut.pt");
  std::filesystem::resize_file(folder + "/cut.pt", size / 2);
  CHECK_THROWS_AS(load_policy_file(folder + "/cut.pt", false), InputError);
  CHECK_THROWS_WITH(PolicySource(folder + "/garbage.pt"), Contains("corrupt or truncated"));
  CHECK_THROWS_WITH(PolicySource("no-such-policy"), Contains("unknown policy"));
}

TEST_CASE("a deployed policy never makes a cut that changes nothing and always finishes", "[sac][policy]") {
  for (const std::string kind : {"paper", "lookahead"}) {
    INFO(kind);
    torch::manual_seed(2);
    auto agent = make_learning_agent(default_sac_config(kind));  // untrained: its choices are arbitrary
    GeneratorOptions options;
    options.holes = true;
    for (const GeneratedShape& shape : test::generated_shapes(20, 4, options)) {
      const GridFace face = make_grid_face(shape.polygon);
      auto policy = agent->deployed_policy("untrained");
      const Decomposition d = decompose_face(face, *policy);
      REQUIRE(d.complete());
      for (const CutRecord& cut : d.cuts) CHECK(cut.n_parts >= 2);
    }
  }
}
