#include "support/catch_torch.h"

#include <filesystem>

#include "core/sac/policy_file.h"
#include "core/sac/trainer.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

TrainingSet generated_set(int count, std::uint64_t seed) {
  TrainingSet set;
  GeneratorOptions options;
  options.max_rects = 5;
  for (const GeneratedShape& shape : test::generated_shapes(count, seed, options)) {
    set.faces.push_back(make_grid_face(shape.polygon));
  }
  return set;
}

SacConfig small_config(const std::string& agent) {
  SacConfig config = default_sac_config(agent);
  config.batch_size = 16;
  config.warmup_steps = 50;
  return config;
}

}  // namespace

TEST_CASE("a seeded short training run improves its test return", "[sac][training]") {
  TrainerOptions options;
  options.episodes = 120;
  options.seed = 5;
  options.eval_every = 120;
  // Evaluated with every cut valued: the pruned deployment's two-step score alone already earns
  // part of the return (lookahead_agent.h), and this checks what the network learns.
  SacConfig config = small_config("lookahead");
  config.deploy_top_k = 0;
  Trainer trainer(config, options, generated_set(12, 50), generated_set(8, 51));
  const double before = trainer.evaluate_test();
  trainer.run({});
  const double after = trainer.history().back().test_return;
  INFO("test return before " << before << ", after " << after);
  CHECK(after > before + 5.0);
}

TEST_CASE("a run resumed from its checkpoint repeats the uninterrupted run exactly", "[sac][training]") {
  for (const std::string kind : {"paper", "lookahead"}) {
  INFO(kind);
  const std::string folder = test::temporary_folder("resume");
  TrainerOptions options;
  options.seed = 9;
  options.eval_every = 3;
  options.checkpoint_every = 3;
  options.threads = 1;

  options.episodes = 6;
  Trainer straight(small_config(kind), options, generated_set(5, 60), generated_set(3, 61));
  straight.run({});

  options.episodes = 3;
  options.checkpoint_path = folder + "/run.checkpoint";
  Trainer first(small_config(kind), options, generated_set(5, 60), generated_set(3, 61));
  first.run({});
  REQUIRE(std::filesystem::exists(options.checkpoint_path));
  options.episodes = 6;
  Trainer second = Trainer::resume(options.checkpoint_path, options, generated_set(5, 60), generated_set(3, 61));
  CHECK(second.episodes_done() == 3);
  second.run({});

  REQUIRE(second.history().size() == straight.history().size());
  for (size_t k = 0; k < straight.history().size(); ++k) {
    CHECK(second.history()[k].ret == straight.history()[k].ret);
    CHECK(second.history()[k].shape == straight.history()[k].shape);
  }
  CHECK(second.history().back().test_return == straight.history().back().test_return);
  }
}

TEST_CASE("stopping a run writes a checkpoint it can resume from", "[sac][training]") {
  const std::string folder = test::temporary_folder("stop");
  TrainerOptions options;
  options.seed = 1;
  options.episodes = 50;
  options.eval_every = 50;
  options.checkpoint_path = folder + "/run.checkpoint";
  Trainer trainer(small_config("lookahead"), options, generated_set(4, 70), generated_set(2, 71));
  int seen = 0;
  trainer.run([&seen](const EpisodeRecord&) { ++seen; }, [&seen] { return seen >= 4; });
  CHECK(trainer.episodes_done() == 4);
  const LoadedPolicy loaded = load_policy_file(options.checkpoint_path, true);
  CHECK(loaded.meta["training"]["episodes_done"] == 4);
  CHECK(loaded.agent->serialize_memory().size() > 100);
}
