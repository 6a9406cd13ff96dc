#include "support/catch_torch.h"

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "core/env/decomposition.h"
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
