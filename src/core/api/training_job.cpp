#include "core/api/training_job.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <random>

#include "core/common/error.h"
#include "core/io/dataset.h"
#include "core/io/input_face.h"
#include "core/io/text_file.h"
#include "core/sac/compute_threads.h"
#include "core/sac/policy_file.h"
#include "core/sac/sac_config.h"
#include "core/sac/training_curves.h"

namespace autoblock {
namespace {

namespace fs = std::filesystem;

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
  if (generated.count > 0) {
    return {{"generated", generated.count},
            {"seed", generated.seed},
            {"min_rects", generated.options.min_rects},
            {"max_rects", generated.options.max_rects},
            {"holes", generated.options.holes}};
  }
  return folder;
}

// Writes the CSV log and the curves of the run so far.
void write_history(const Trainer& trainer, const std::string& log, const std::string& curves, RewardPreset reward) {
  std::string csv = training_csv_header();
  for (const EpisodeRecord& r : trainer.history()) csv += training_csv_row(r);
  write_text_file(log, csv);
  if (!trainer.history().empty()) {
    write_text_file(curves, training_curves_svg(trainer.history(), {},
                                                "AutoBlock SAC training (" + reward_preset_name(reward) + " reward)"));
  }
}

}  // namespace

TrainingSet load_training_set(const std::string& folder, const GeneratedSet& generated, const std::string& what) {
  TrainingSet set;
  if (generated.count > 0) {
    std::mt19937_64 rng(generated.seed);
    for (int k = 0; k < generated.count; ++k) {
      set.faces.push_back(make_grid_face(generate_shape(rng, generated.options).polygon));
      char name[32];
      std::snprintf(name, sizeof name, "generated_%04d", k);
      set.names.push_back(name);
    }
    return set;
  }
  if (folder.empty()) throw InputError("no " + what + " data: give a folder of faces or generate shapes");
  std::vector<std::string> files;
  try {
    files = collect_shape_files({folder});
  } catch (const InputError& e) {
    throw InputError(what + " data: " + e.what());
  }
  for (const std::string& file : files) {
    set.faces.push_back(load_input_face(file).grid);
    set.names.push_back(fs::path(file).filename().string());
  }
  return set;
}

TrainingOutcome run_training_job(const TrainingJob& job, const TrainingCallbacks& callbacks) {
  if (job.output.empty()) throw InputError("no output file for the trained policy");
  require_parent_folder(job.output, "the policy file");
  if (job.episodes < 1) throw InputError("train at least one episode");
  if (job.eval_every < 1) throw InputError("evaluate at least every episode (eval_every >= 1)");
  TrainingOutcome outcome;
  outcome.checkpoint = job.checkpoint.empty() ? job.output + ".checkpoint" : job.checkpoint;
  outcome.log = sibling(job.output, ".csv");
  outcome.curves = sibling(job.output, "-curves.svg");
  outcome.episodes = job.episodes;
  require_parent_folder(outcome.checkpoint, "the checkpoint");
  if (job.resume && !fs::exists(outcome.checkpoint)) {
    throw InputError("nothing to resume: the checkpoint " + outcome.checkpoint + " does not exist");
  }
  // Checked before the data loads (which can take a while).
  SacConfig config;
  if (!job.resume) {
    config = default_sac_config(job.agent);
    config.reward = reward_preset_by_name(job.reward);
  }

  TrainingSet train = load_training_set(job.train_folder, job.train_generate, "training");
  TrainingSet test = load_training_set(job.test_folder, job.test_generate, "test");
  TrainerOptions options;
  options.episodes = job.episodes;
  options.seed = job.seed;
  options.threads = std::max(1, job.threads);
  options.eval_every = job.eval_every;
  options.checkpoint_every = job.eval_every;
  options.checkpoint_path = outcome.checkpoint;
  options.max_steps = job.max_steps;
  std::unique_ptr<Trainer> trainer =
      job.resume ? std::make_unique<Trainer>(Trainer::resume(outcome.checkpoint, options, std::move(train), std::move(test)))
                 : std::make_unique<Trainer>(config, options, std::move(train), std::move(test));
  const RewardPreset reward = trainer->agent()->config().reward;
  outcome.reward = reward_preset_name(reward);

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
    write_history(*trainer, outcome.log, outcome.curves, reward);
    throw;
  }
  write_history(*trainer, outcome.log, outcome.curves, reward);
  outcome.episodes_done = trainer->episodes_done();
  outcome.cancelled = trainer->episodes_done() < job.episodes;
  const TrainingSpeed speed = training_speed(trainer->history());
  outcome.final_test_return = speed.final_test_return;
  if (outcome.cancelled) return outcome;
  save_policy_file(job.output, *trainer->agent(),
                   {{"episodes", trainer->episodes_done()},
                    {"seed", job.seed},
                    {"train", set_json(job.train_folder, job.train_generate)},
                    {"test", set_json(job.test_folder, job.test_generate)},
                    {"final_test_return", speed.final_test_return},
                    {"episodes_to_95", speed.episodes_to_95},
                    {"seconds_to_95", speed.seconds_to_95},
                    {"wall_seconds", trainer->history().empty() ? 0.0 : trainer->history().back().wall_seconds}},
                   false);
  outcome.policy_file = job.output;
  return outcome;
}

}  // namespace autoblock
