#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/sac/policy_file.h"
#include "core/sac/policy_source.h"
#include "core/sac/sac_policy.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

TEST_CASE("a policy file round-trips the agent exactly", "[sac][policy]") {
  torch::manual_seed(11);
  SacConfig config;
  config.reward = RewardPreset::Mesh;
  SacAgent agent(config);
  const std::string path = test::temporary_folder("policy") + "/p.pt";
  save_policy_file(path, agent, {{"note", "test"}}, nullptr);
  const LoadedPolicy loaded = load_policy_file(path, false);
  CHECK(loaded.meta["kind"] == "policy");
  CHECK(loaded.meta["training"]["note"] == "test");
  CHECK(loaded.agent->config().reward == RewardPreset::Mesh);
  const auto state = make_part_state(test::grid_face_of(test::l_shape()).whole, config.graph);
  CHECK(loaded.agent->vertex_values(*state) == agent.vertex_values(*state));
  CHECK(loaded.agent->direction_probabilities(state->observations[2]) == agent.direction_probabilities(state->observations[2]));
  CHECK_THROWS_WITH(load_policy_file(path, true), Contains("not a training checkpoint"));
}

TEST_CASE("missing, corrupt, truncated and foreign policy files are clear errors", "[sac][policy][errors]") {
  const std::string folder = test::temporary_folder("bad-policy");
  CHECK_THROWS_WITH(load_policy_file(folder + "/none.pt", false), Contains("no such policy file"));
  std::ofstream(folder + "/garbage.pt") << "this is not a policy";
  CHECK_THROWS_WITH(load_policy_file(folder + "/garbage.pt", false), Contains("corrupt or truncated"));
  torch::manual_seed(1);
  SacAgent agent(SacConfig{});
  save_policy_file(folder + "/good.pt", agent, {}, nullptr);
  const auto size = std::filesystem::file_size(folder + "/good.pt");
  std::filesystem::copy_file(folder + "/good.pt", folder + "/cut.pt");
  std::filesystem::resize_file(folder + "/cut.pt", size / 2);
  CHECK_THROWS_AS(load_policy_file(folder + "/cut.pt", false), InputError);
  CHECK_THROWS_WITH(PolicySource(folder + "/garbage.pt"), Contains("corrupt or truncated"));
  CHECK_THROWS_WITH(PolicySource("no-such-policy"), Contains("unknown policy"));
}

TEST_CASE("a deployed policy never makes a cut that changes nothing and always finishes", "[sac][policy]") {
  torch::manual_seed(2);
  auto agent = std::make_shared<SacAgent>(SacConfig{});  // untrained: its choices are arbitrary
  GeneratorOptions options;
  options.holes = true;
  for (const GeneratedShape& shape : test::generated_shapes(20, 4, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    SacPolicy policy(agent, "untrained");
    const Decomposition d = decompose_face(face, policy);
    REQUIRE(d.complete());
    for (const CutRecord& cut : d.cuts) CHECK(cut.n_parts >= 2);
  }
}
