// The learned-policy runtime (core/api/learned_runtime.h) over the agents, policy files and the
// trainer: the one entry point of libautoblock_learn.so.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/api/learned_runtime.h"
#include "core/api/policy_source.h"
#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/io/text_file.h"
#include "core/raster/picture_file.h"
#include "core/sac/compute_threads.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/policy_file.h"
#include "core/region/region_search.h"
#include "core/sac/sac_config.h"
#include "core/sac/trainer.h"
#include "core/sac/training_curves.h"

namespace autoblock {
namespace {

namespace fs = std::filesystem;

// A policy file's agents: one for every face, or (version 2) one for rectilinear faces and one for
// general faces.
class AgentPolicy : public LearnedPolicy {
 public:
  explicit AgentPolicy(const LoadedPolicy& loaded) : agent_(loaded.agent), general_(loaded.general_agent()) {}
  RewardPreset reward() const override { return agent_->config().reward; }
  std::unique_ptr<Policy> deployed_policy(const std::string& name) override { return agent_->deployed_policy(name); }
  std::vector<float> vertex_scores(const Episode& episode) override { return agent_->vertex_scores(episode); }
  std::unique_ptr<RegionPolicy> deployed_region_policy(const std::string& name) override {
    return general_->deployed_region_policy(name);
  }
  std::vector<float> region_vertex_scores(const RegionEpisode& episode) override {
    return general_->region_vertex_scores(episode);
  }
  bool general_network() const override { return general_ != agent_; }

 private:
  std::shared_ptr<LearningAgent> agent_, general_;
};

std::string sibling(const std::string& path, const std::string& suffix) {
  const fs::path p(path);
  return (p.parent_path() / (p.stem().string() + suffix)).string();
}

void require_parent_folder(const std::string& path, const std::string& what) {
  const fs::path p = fs::absolute(fs::path(path));
  std::error_code ec;
  if (!fs::is_directory(p.parent_path(), ec)) {
    throw InputError(what + " " + path + ": the folder " + p.parent_path().string() + " does not exist");
  }
}

nlohmann::json set_json(const std::string& folder, const GeneratedSet& generated) {
  if (generated.total() > 0) {
    nlohmann::json j = {{"generated", generated.count},
                        {"seed", generated.seed},
                        {"min_rects", generated.options.min_rects},
                        {"max_rects", generated.options.max_rects},
                        {"holes", generated.options.holes}};
    if (generated.general > 0) j["general"] = generated.general;
    if (generated.arcs > 0) j["arcs"] = generated.arcs;
    return j;
  }
  return folder;
}

constexpr double kReferenceOptimalSeconds = 30.0;

// A baseline's mean return over the set (the curves' reference lines): "optimal" or "greedy" on
// rectilinear faces; on general faces, where no exact optimum is known, "optimal" is the search.
double mean_return(const TrainingSet& set, const std::string& policy, RewardPreset reward) {
  if (set.size() == 0) return 0.0;
  double total = 0.0;
  EpisodeOptions options;
  options.reward = reward;
  for (const GridFace& face : set.faces) {
    BaselineOptions baseline;
    baseline.reward = reward;
    baseline.optimal_seconds = kReferenceOptimalSeconds;
    auto p = make_baseline_policy(policy, face.size, baseline);
    total += decompose_face(face, *p, options).total_return;
  }
  if (!set.general.empty()) {
    RegionEpisodeOptions region_options;
    region_options.reward = reward;
    const auto lock = lock_general_engine();
    for (const Region& face : set.general) {
      std::unique_ptr<RegionPolicy> p;
      if (policy == "optimal") {
        p = std::make_unique<RegionSearchPolicy>();
      } else {
        p = std::make_unique<RegionGreedyPolicy>();
      }
      total += decompose_region(face, *p, region_options).total_return;
    }
  }
  return total / static_cast<double>(set.size());
}

struct Reporting {
  std::string log, curves, title;
  std::vector<ChartReference> references;

  // Writes the CSV log and the curves of the run so far.
  void write(const Trainer& trainer) const {
    std::string csv = training_csv_header();
    for (const EpisodeRecord& r : trainer.history()) csv += training_csv_row(r);
    write_text_file(log, csv);
    if (!trainer.history().empty()) write_picture(curves, training_curves_svg(trainer.history(), references, title));
  }
};

SacConfig job_config(const TrainingJob& job) {
  SacConfig config = default_sac_config(job.agent);
  config.reward = reward_preset_by_name(job.reward);
  if (!job.value_network.empty()) config.value_network = job.value_network;
  if (!job.bootstrap.empty()) {
    if (job.bootstrap != "graph" && job.bootstrap != "critics") {
      throw InputError("unknown bootstrap '" + job.bootstrap + "' (expected graph or critics)");
    }
    config.bootstrap = job.bootstrap == "graph" ? Bootstrap::Graph : Bootstrap::Critics;
  }
  if (job.batch_size > 0) config.batch_size = job.batch_size;
  if (job.lr_final > 0.0) config.lr_final_fraction = job.lr_final;
  if (job.weight_average >= 0.0) config.weight_average_decay = job.weight_average;
  if (job.deploy_views > 0) config.deploy_views = job.deploy_views;
  return with_settings(config, job.settings);
}

TrainingOutcome train(const TrainingJob& job, const TrainingCallbacks& callbacks) {
  if (job.output.empty()) throw InputError("no output file for the trained policy");
  require_parent_folder(job.output, "the policy file");
  if (job.episodes < 1) throw InputError("train at least one episode");
  if (job.eval_every < 1) throw InputError("evaluate at least every episode (eval_every >= 1)");
  TrainingOutcome outcome;
  outcome.checkpoint = job.checkpoint.empty() ? job.output + ".checkpoint" : job.checkpoint;
  outcome.log = job.log.empty() ? sibling(job.output, ".csv") : job.log;
  outcome.curves = job.curves.empty() ? sibling(job.output, "-curves.svg") : job.curves;
  outcome.episodes = job.episodes;
  check_picture_path(outcome.curves, "the curves picture");
  require_parent_folder(outcome.checkpoint, "the checkpoint");
  require_parent_folder(outcome.log, "the log");
  // A resumed run keeps the checkpoint's configuration, except the deployment's (the lookahead
  // agent's deploy_views and deploy_top_k): they change nothing in training, so a finished run
  // resumed with them writes the policy a fresh run with them would have written.
  for (const std::string& setting : job.resume ? job.settings : std::vector<std::string>{}) {
    const std::string key = setting.substr(0, setting.find('='));
    if (key != "deploy_views" && key != "deploy_top_k") {
      throw InputError("configuration settings apply to a fresh run: a resumed run keeps the checkpoint's "
                       "(except deploy_views and deploy_top_k)");
    }
  }
  if (job.resume && !job.init.empty()) {
    throw InputError("an initial policy starts a fresh run: a resumed run keeps its checkpoint's networks");
  }
  if (job.resume && !fs::exists(outcome.checkpoint)) {
    throw InputError("nothing to resume: the checkpoint " + outcome.checkpoint + " does not exist");
  }
  // Checked before the data loads (which can take a while).
  SacConfig config;
  if (!job.resume) config = job_config(job);
  LoadedPolicy initial;
  if (!job.init.empty()) initial = load_policy_file(policy_file_path(job.init), false);

  TrainingSet train_set = load_training_set(job.train_folder, job.train_generate, "training");
  // A policy with two networks starts a run on general faces alone from its network for them.
  const std::shared_ptr<LearningAgent> initial_agent =
      train_set.faces.empty() && !train_set.general.empty() ? initial.general_agent() : initial.agent;
  TrainingSet test_set = load_training_set(job.test_folder, job.test_generate, "test");
  TrainerOptions options;
  options.episodes = job.episodes;
  options.seed = job.seed;
  options.threads = std::max(1, job.threads);
  options.eval_every = job.eval_every;
  options.checkpoint_every = job.eval_every;
  options.checkpoint_path = outcome.checkpoint;
  options.max_steps = job.max_steps;
  std::unique_ptr<Trainer> trainer =
      job.resume ? std::make_unique<Trainer>(Trainer::resume(outcome.checkpoint, options, std::move(train_set),
                                                             std::move(test_set)))
                 : std::make_unique<Trainer>(config, options, std::move(train_set), std::move(test_set));
  if (initial_agent) trainer->agent()->copy_weights_from(*initial_agent);
  if (job.resume && !job.settings.empty()) {
    const auto lookahead = std::dynamic_pointer_cast<LookaheadAgent>(trainer->agent());
    if (!lookahead) throw InputError("deploy_views and deploy_top_k apply to the lookahead agent only");
    const SacConfig deployed = with_settings(lookahead->config(), job.settings);
    lookahead->set_deploy_views(deployed.deploy_views);
    lookahead->set_deploy_top_k(deployed.deploy_top_k);
  }
  const RewardPreset reward = trainer->agent()->config().reward;
  outcome.reward = reward_preset_name(reward);
  const TrainingSet& test = trainer->test_set();
  if (callbacks.on_status) {
    char line[240];
    std::snprintf(line, sizeof line, "reference returns of the test faces: the exact search on %zu (up to %g s each), "
                  "the search on %zu general ones (up to %g s each), greedy on all", test.faces.size(),
                  kReferenceOptimalSeconds, test.general.size(), RegionSearchOptions{}.time_limit);
    callbacks.on_status(line);
  }
  outcome.optimal_test_return = mean_return(test, "optimal", reward);
  outcome.greedy_test_return = mean_return(test, "greedy", reward);
  Reporting reporting{outcome.log, outcome.curves, "AutoBlock SAC training (" + outcome.reward + " reward)",
                      {{test.general.empty() ? "optimal (test set)" : "optimal / search (test set)", "#2ca02c",
                        outcome.optimal_test_return},
                       {"greedy (test set)", "#ff7f0e", outcome.greedy_test_return}}};

  struct Deployment {  // back to one thread for deployment (sac/compute_threads.h), however the run ends
    ~Deployment() { set_compute_threads(1); }
  } deployment;
  if (callbacks.on_episode) {
    for (const EpisodeRecord& record : trainer->history()) callbacks.on_episode(record, true);
  }
  try {
    trainer->run([&](const EpisodeRecord& record) {
      if (callbacks.on_episode) callbacks.on_episode(record, false);
    },
                 callbacks.should_stop);
  } catch (...) {
    // A failed callback (or episode): keep what was learned for a resume.
    trainer->save_checkpoint(outcome.checkpoint);
    reporting.write(*trainer);
    throw;
  }
  reporting.write(*trainer);
  outcome.episodes_done = trainer->episodes_done();
  outcome.cancelled = trainer->episodes_done() < job.episodes;
  const TrainingSpeed speed = training_speed(trainer->history());
  outcome.final_test_return = speed.final_test_return;
  outcome.episodes_to_95 = speed.episodes_to_95;
  outcome.seconds_to_95 = speed.seconds_to_95;
  outcome.rule_95 = speed.rule;
  outcome.wall_seconds = trainer->history().empty() ? 0.0 : trainer->history().back().wall_seconds;
  if (outcome.cancelled) return outcome;
  save_policy_file(job.output, *trainer->agent(),
                   {{"episodes", trainer->episodes_done()},
                    {"seed", job.seed},
                    {"train", set_json(job.train_folder, job.train_generate)},
                    {"test", set_json(job.test_folder, job.test_generate)},
                    {"init", job.init},
                    {"final_test_return", speed.final_test_return},
                    {"optimal_test_return", outcome.optimal_test_return},
                    {"greedy_test_return", outcome.greedy_test_return},
                    {"episodes_to_95", speed.episodes_to_95},
                    {"seconds_to_95", speed.seconds_to_95},
                    {"wall_seconds", outcome.wall_seconds}},
                   false);
  outcome.policy_file = job.output;
  return outcome;
}

class Runtime : public LearnedRuntime {
 public:
  Runtime() { set_compute_threads(1); }  // deployment: one thread per decomposition (training sets its own)
  std::shared_ptr<LearnedPolicy> load_policy(const std::string& path) override {
    return std::make_shared<AgentPolicy>(load_policy_file(path, false));
  }
  std::string combine_policies(const std::string& grid, const std::string& general, const std::string& output) override {
    require_parent_folder(output, "the policy file");
    const nlohmann::json meta = combine_policy_files(grid, general, output);
    return meta.dump();
  }
  TrainingOutcome run_training_job(const TrainingJob& job, const TrainingCallbacks& callbacks) override {
    return train(job, callbacks);
  }
};

}  // namespace
}  // namespace autoblock

extern "C" __attribute__((visibility("default"))) autoblock::LearnedRuntime* autoblock_learned_runtime() {
  static autoblock::Runtime runtime;
  return &runtime;
}
