#include "support/catch_torch.h"

#include "core/api/training_job.h"
#include "core/common/error.h"
#include "core/geometry/grid_face.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/policy_file.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("a finished run resumed with deployment settings writes the same network deployed so", "[api][train]") {
  const std::string folder = test::temporary_folder("training-job-deploy");
  TrainingJob job;
  job.output = folder + "/p.pt";
  job.train_generate.count = 3;
  job.train_generate.seed = 70;
  job.test_generate.count = 2;
  job.test_generate.seed = 71;
  job.episodes = 2;
  job.eval_every = 1;
  job.seed = 3;
  run_training_job(job, {});
  const LoadedPolicy first = load_policy_file(job.output, false);
  CHECK(first.agent->config().deploy_top_k == default_sac_config("lookahead").deploy_top_k);

  TrainingJob again = job;
  again.resume = true;
  again.checkpoint = job.output + ".checkpoint";
  again.output = folder + "/q.pt";
  again.settings = {"deploy_top_k=3", "deploy_views=1"};
  const TrainingOutcome outcome = run_training_job(again, {});
  CHECK(outcome.episodes_done == 2);
  const LoadedPolicy second = load_policy_file(again.output, false);
  CHECK(second.agent->config().deploy_top_k == 3);
  CHECK(second.agent->config().deploy_views == 1);
  // The network is the trained one: the same values.
  const auto a = std::dynamic_pointer_cast<LookaheadAgent>(first.agent);
  const auto b = std::dynamic_pointer_cast<LookaheadAgent>(second.agent);
  REQUIRE(a);
  REQUIRE(b);
  const GridFace face = make_grid_face(test::generated_shapes(1, 72, GeneratorOptions{}).front().polygon);
  const auto state = make_part_state(face.whole, a->state_options(face.size));
  CHECK(a->deployed_values({state.get()}) == b->deployed_values({state.get()}));

  // Settings that change training still apply to fresh runs only.
  TrainingJob changed = again;
  changed.settings = {"gamma=0.5"};
  CHECK_THROWS_AS(run_training_job(changed, {}), InputError);
}

TEST_CASE("a run started from a policy's weights starts from that policy's network", "[api][train]") {
  const std::string folder = test::temporary_folder("training-job-init");
  TrainingJob job;
  job.output = folder + "/p.pt";
  job.train_generate.count = 3;
  job.train_generate.seed = 80;
  job.test_generate.count = 2;
  job.test_generate.seed = 81;
  job.episodes = 3;
  job.eval_every = 3;
  job.seed = 4;
  job.settings = {"warmup_steps=5"};  // some updates: the trained network is not the initial one
  run_training_job(job, {});

  // A fresh run of one episode (no update: within the warm-up) from p.pt, and one from random weights.
  TrainingJob warm;
  warm.output = folder + "/warm.pt";
  warm.train_generate = job.train_generate;
  warm.test_generate = job.test_generate;
  warm.episodes = 1;
  warm.eval_every = 1;
  warm.seed = 5;
  warm.init = job.output;
  run_training_job(warm, {});
  TrainingJob cold = warm;
  cold.output = folder + "/cold.pt";
  cold.init.clear();
  run_training_job(cold, {});

  auto lookahead = [](const std::string& path) {
    const auto agent = std::dynamic_pointer_cast<LookaheadAgent>(load_policy_file(path, false).agent);
    REQUIRE(agent);
    return agent;
  };
  const auto trained = lookahead(job.output), started = lookahead(warm.output), fresh = lookahead(cold.output);
  const GridFace face = make_grid_face(test::generated_shapes(1, 82, GeneratorOptions{}).front().polygon);
  const auto state = make_part_state(face.whole, trained->state_options(face.size));
  CHECK(started->deployed_values({state.get()}) == trained->deployed_values({state.get()}));
  CHECK(fresh->deployed_values({state.get()}) != trained->deployed_values({state.get()}));

  // Bad starts: with a resume, from the paper agent's policy, from another value network, a missing file.
  TrainingJob resumed = warm;
  resumed.resume = true;
  resumed.checkpoint = job.output + ".checkpoint";
  CHECK_THROWS_WITH(run_training_job(resumed, {}), Catch::Matchers::Contains("fresh run"));
  TrainingJob paper = job;
  paper.output = folder + "/paper.pt";
  paper.agent = "paper";
  paper.settings.clear();
  paper.episodes = 1;
  run_training_job(paper, {});
  TrainingJob foreign = warm;
  foreign.init = paper.output;
  CHECK_THROWS_WITH(run_training_job(foreign, {}), Catch::Matchers::Contains("paper agent's"));
  TrainingJob other_network = warm;
  other_network.value_network = "paper";
  CHECK_THROWS_WITH(run_training_job(other_network, {}), Catch::Matchers::Contains("value network"));
  TrainingJob missing = warm;
  missing.init = folder + "/none.pt";
  CHECK_THROWS_AS(run_training_job(missing, {}), InputError);
}
