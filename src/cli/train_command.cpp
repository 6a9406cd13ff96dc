// autoblock train --train DIR --test DIR [--episodes N] [--seed S] [--out POLICY]
//                 [--resume CHECKPOINT] [--threads T] [--reward paper|mesh] ...
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/commands.h"
#include "cli/progress_bar.h"
#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/io/dataset.h"
#include "core/io/input_face.h"
#include "core/io/text_file.h"
#include "core/raster/picture_file.h"
#include "core/sac/policy_file.h"
#include "core/sac/trainer.h"
#include "core/sac/training_curves.h"

namespace autoblock::cli {
namespace {

std::atomic<bool> interrupted{false};
extern "C" void on_interrupt(int) { interrupted = true; }

TrainingSet load_set(const std::string& folder) {
  TrainingSet set;
  for (const std::string& file : collect_shape_files({folder})) {
    set.faces.push_back(load_input_face(file).grid);
    set.names.push_back(std::filesystem::path(file).filename().string());
  }
  return set;
}

std::string sibling(const std::string& path, const std::string& suffix) {
  std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + suffix)).string();
}

double mean_return(const TrainingSet& set, const std::string& policy, RewardPreset reward) {
  double total = 0.0;
  EpisodeOptions options;
  options.reward = reward;
  for (const GridFace& face : set.faces) {
    BaselineOptions baseline;
    baseline.reward = reward;
    baseline.optimal_seconds = 30;
    auto p = make_baseline_policy(policy, face.size, baseline);
    total += decompose_face(face, *p, options).total_return;
  }
  return total / static_cast<double>(set.faces.size());
}

}  // namespace

void add_train_command(CLI::App& app) {
  struct Arguments {
    std::string train, test, out = "policy.pt", resume, checkpoint, log, curves;
    std::string agent = "lookahead", reward = "paper", value_network, bootstrap = "graph";
    int episodes = 1500, threads = 2, eval_every = 25, batch_size = 0, views = 0;
    double lr_final = 0.0, average = -1.0;
    std::uint64_t seed = 0;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("train", "Train a decomposition policy with Soft Actor-Critic.");
  command->add_option("--train", args->train, "folder of training faces")->required();
  command->add_option("--test", args->test, "folder of test faces (evaluated deterministically)")->required();
  command->add_option("--episodes", args->episodes, "total episodes (a resumed run counts those already done)")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  command->add_option("--seed", args->seed, "seed (with one thread a seeded run repeats exactly)")->capture_default_str();
  command->add_option("--out", args->out, "the trained policy file")->capture_default_str();
  command->add_option("--resume", args->resume, "continue the run saved in this checkpoint");
  command->add_option("--threads", args->threads, "threads for the networks' arithmetic")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command->add_option("--agent", args->agent,
                      "lookahead (default: one cut of lookahead, beyond the paper) | paper (the paper's SAC, faithfully)")
      ->check(CLI::IsMember({"lookahead", "paper"}))
      ->capture_default_str();
  command->add_option("--reward", args->reward, "reward preset: paper (Eq. 1) | mesh")
      ->check(CLI::IsMember({"paper", "mesh"}))
      ->capture_default_str();
  command->add_option("--value-network", args->value_network, "value network preset: small | paper (default small)")
      ->check(CLI::IsMember({"small", "paper"}));
  command->add_option("--bootstrap", args->bootstrap, "paper agent: children's values in the Bellman target: graph | critics")
      ->check(CLI::IsMember({"graph", "critics"}))
      ->capture_default_str();
  command->add_option("--batch-size", args->batch_size, "replay batch size (default from the configuration)")
      ->check(CLI::Range(1, 4096));
  command->add_option("--lr-final", args->lr_final,
                      "lookahead agent: the learning rate's fraction left at the last episode, after a half-cosine decay "
                      "(1: constant; default from the configuration)")
      ->check(CLI::Range(1e-6, 1.0));
  command->add_option("--weight-average", args->average,
                      "lookahead agent: deploy an exponential moving average of the weights with this decay per update "
                      "(0: the trained weights; default from the configuration)")
      ->check(CLI::Range(0.0, 0.9999));
  command->add_option("--deploy-views", args->views,
                      "lookahead agent, deployed: average each piece's value over this many of the square's symmetries "
                      "(1-8; default from the configuration)")
      ->check(CLI::Range(1, 8));
  command->add_option("--eval-every", args->eval_every, "episodes between test evaluations and checkpoints")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--checkpoint", args->checkpoint, "checkpoint file (default: POLICY.checkpoint)");
  command->add_option("--log", args->log, "CSV log, one line per episode (default: POLICY's stem + .csv)");
  command->add_option("--curves", args->curves, "reward curves picture, .png or .svg (default: POLICY's stem + -curves.png)");
  command->callback([args] {
    if (args->checkpoint.empty()) args->checkpoint = args->out + ".checkpoint";
    if (args->log.empty()) args->log = sibling(args->out, ".csv");
    if (args->curves.empty()) args->curves = sibling(args->out, "-curves.png");
    check_picture_path(args->curves, "--curves");
    TrainingSet train = load_set(args->train);
    TrainingSet test = load_set(args->test);
    TrainerOptions options;
    options.episodes = args->episodes;
    options.seed = args->seed;
    options.threads = args->threads;
    options.eval_every = args->eval_every;
    options.checkpoint_every = args->eval_every;
    options.checkpoint_path = args->checkpoint;
    std::unique_ptr<Trainer> trainer;
    if (!args->resume.empty()) {
      trainer = std::make_unique<Trainer>(Trainer::resume(args->resume, options, train, test));
    } else {
      SacConfig config = default_sac_config(args->agent);
      config.reward = reward_preset_by_name(args->reward);
      if (!args->value_network.empty()) config.value_network = args->value_network;
      config.bootstrap = args->bootstrap == "graph" ? Bootstrap::Graph : Bootstrap::Critics;
      if (args->batch_size > 0) config.batch_size = args->batch_size;
      if (args->lr_final > 0.0) config.lr_final_fraction = args->lr_final;
      if (args->average >= 0.0) config.weight_average_decay = args->average;
      if (args->views > 0) config.deploy_views = args->views;
      trainer = std::make_unique<Trainer>(config, options, train, test);
    }
    const RewardPreset reward = trainer->agent()->config().reward;
    const double optimal = mean_return(test, "optimal", reward), greedy = mean_return(test, "greedy", reward);

    // The CSV: rewritten from the history (a resume keeps what came before), then appended.
    std::string csv = training_csv_header();
    for (const EpisodeRecord& r : trainer->history()) csv += training_csv_row(r);
    write_text_file(args->log, csv);
    std::ofstream log(args->log, std::ios::app);

    interrupted = false;
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    ProgressBar progress(args->episodes, "train");
    double window = 0.0;
    std::vector<double> recent;
    double last_test = 0.0;
    trainer->run(
        [&](const EpisodeRecord& r) {
          log << training_csv_row(r) << std::flush;
          recent.push_back(r.ret);
          window += r.ret;
          if (recent.size() > 10) window -= recent[recent.size() - 11];
          if (r.evaluated) last_test = r.test_return;
          char note[128];
          std::snprintf(note, sizeof note, "avg10 %.2f  test %.2f (optimal %.2f)", window / std::min<size_t>(recent.size(), 10),
                        last_test, optimal);
          progress.update(r.episode, note);
        },
        [] { return interrupted.load(); });
    progress.finish();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);

    const std::vector<ChartReference> references{{"optimal (test set)", "#2ca02c", optimal},
                                                 {"greedy (test set)", "#ff7f0e", greedy}};
    const std::string svg = training_curves_svg(trainer->history(), references,
                                                "AutoBlock SAC training (" + reward_preset_name(reward) + " reward)");
    write_picture(args->curves, svg);
    if (trainer->episodes_done() < args->episodes) {
      std::cout << "stopped after " << trainer->episodes_done() << " of " << args->episodes
                << " episodes; resume with: autoblock train --resume " << args->checkpoint << " ...\n";
      std::cout << "  checkpoint: " << args->checkpoint << "\n  log:        " << args->log << "\n";
      return;
    }
    const TrainingSpeed speed = training_speed(trainer->history());
    save_policy_file(args->out, *trainer->agent(),
                     {{"episodes", trainer->episodes_done()},
                      {"seed", args->seed},
                      {"train", args->train},
                      {"test", args->test},
                      {"final_test_return", speed.final_test_return},
                      {"optimal_test_return", optimal},
                      {"greedy_test_return", greedy},
                      {"episodes_to_95", speed.episodes_to_95},
                      {"seconds_to_95", speed.seconds_to_95},
                      {"wall_seconds", trainer->history().back().wall_seconds}},
                     false);
    std::printf("trained %d episodes in %.1f min: final test return %.3f (optimal %.3f, greedy %.3f)\n",
                trainer->episodes_done(), trainer->history().back().wall_seconds / 60.0, speed.final_test_return, optimal,
                greedy);
    if (speed.episodes_to_95 > 0) {
      std::printf("reached the 95%% mark (%s) at episode %d after %.1f min\n", speed.rule.c_str(), speed.episodes_to_95,
                  speed.seconds_to_95 / 60.0);
    }
    std::printf("  policy:     %s\n  checkpoint: %s\n  log:        %s\n  curves:     %s\n", args->out.c_str(),
                args->checkpoint.c_str(), args->log.c_str(), args->curves.c_str());
  });
}

}  // namespace autoblock::cli
