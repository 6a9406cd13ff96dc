// autoblock train --train DIR --test DIR [--episodes N] [--seed S] [--out POLICY]
//                 [--resume CHECKPOINT | --init POLICY] [--threads T] [--reward paper|mesh] ...
// The training job of core/api (training_job.h) with a terminal around it: a progress bar, Ctrl-C.
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#include "cli/commands.h"
#include "cli/progress_bar.h"
#include "core/api/training_job.h"
#include "core/raster/picture_file.h"

namespace autoblock::cli {
namespace {

std::atomic<bool> interrupted{false};
extern "C" void on_interrupt(int) { interrupted = true; }

std::string sibling(const std::string& path, const std::string& suffix) {
  std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + suffix)).string();
}

}  // namespace

void add_train_command(CLI::App& app) {
  struct Arguments {
    std::string train, test, out = "policy.pt", resume, init, checkpoint, log, curves;
    std::string agent = "lookahead", reward = "paper", value_network, bootstrap = "graph";
    int episodes = 1500, threads = 2, eval_every = 25, batch_size = 0, views = 0;
    double lr_final = 0.0, average = -1.0;
    std::uint64_t seed = 0;
    std::vector<std::string> settings;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("train", "Train a decomposition policy with Soft Actor-Critic.");
  command->add_option("--train", args->train, "folder of training faces (rectilinear; the lookahead agent also learns on faces with edges at other angles or arcs in it)")->required();
  command->add_option("--test", args->test, "folder of test faces (evaluated deterministically)")->required();
  command->add_option("--episodes", args->episodes, "total episodes (a resumed run counts those already done)")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  command->add_option("--seed", args->seed, "seed (with one thread a seeded run repeats exactly)")->capture_default_str();
  command->add_option("--out", args->out, "the trained policy file")->capture_default_str();
  command->add_option("--resume", args->resume, "continue the run saved in this checkpoint");
  command->add_option("--init", args->init,
                      "a fresh run starting from this policy's weights (a shipped name such as sac-mesh, or a file; "
                      "the same agent and value network)");
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
  command->add_option("--set", args->settings,
                      "KEY=VALUE: set a field of the agent's configuration (repeatable; for ablations), e.g. "
                      "--set initial_direction_temperature=1 --set actor_output_relu=false")
      ->type_name("KEY=VALUE");
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
    TrainingJob job;
    job.output = args->out;
    job.checkpoint = args->checkpoint;
    job.resume = !args->resume.empty();
    if (job.resume) job.checkpoint = args->resume;
    job.init = args->init;
    job.train_folder = args->train;
    job.test_folder = args->test;
    job.episodes = args->episodes;
    job.seed = args->seed;
    job.reward = args->reward;
    job.agent = args->agent;
    job.threads = args->threads;
    job.eval_every = args->eval_every;
    job.value_network = args->value_network;
    job.bootstrap = args->bootstrap;
    job.batch_size = args->batch_size;
    job.lr_final = args->lr_final;
    job.weight_average = args->average;
    job.deploy_views = args->views;
    job.settings = args->settings;
    job.log = args->log;
    job.curves = args->curves;

    interrupted = false;
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    ProgressBar progress(args->episodes, "train");
    double window = 0.0, last_test = 0.0;
    std::vector<double> recent;
    TrainingCallbacks callbacks;
    callbacks.on_episode = [&](const EpisodeRecord& r, bool earlier) {
      recent.push_back(r.ret);
      window += r.ret;
      if (recent.size() > 10) window -= recent[recent.size() - 11];
      if (r.evaluated) last_test = r.test_return;
      char note[128];
      std::snprintf(note, sizeof note, "avg10 %.2f  test %.2f", window / std::min<size_t>(recent.size(), 10), last_test);
      progress.update(r.episode, note);
      // Without a terminal (a log file, a background run) a line at every evaluation instead.
      if (!progress.drawn() && r.evaluated && !earlier) {
        std::fprintf(stderr, "train: episode %d of %d, %.1f min: %s\n", r.episode, args->episodes, r.wall_seconds / 60.0,
                     note);
        std::fflush(stderr);
      }
    };
    callbacks.should_stop = [] { return interrupted.load(); };
    callbacks.on_status = [](const std::string& line) {
      std::fprintf(stderr, "train: %s...\n", line.c_str());
      std::fflush(stderr);
    };
    const TrainingOutcome outcome = run_training_job(job, callbacks);
    progress.finish();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);

    if (outcome.cancelled) {
      std::cout << "stopped after " << outcome.episodes_done << " of " << args->episodes
                << " episodes; resume with: autoblock train --resume " << outcome.checkpoint << " ...\n";
      std::cout << "  checkpoint: " << outcome.checkpoint << "\n  log:        " << outcome.log << "\n";
      return;
    }
    std::printf("trained %d episodes in %.1f min: final test return %.3f (optimal %.3f, greedy %.3f)\n",
                outcome.episodes_done, outcome.wall_seconds / 60.0, outcome.final_test_return,
                outcome.optimal_test_return, outcome.greedy_test_return);
    if (outcome.episodes_to_95 > 0) {
      std::printf("reached the 95%% mark (%s) at episode %d after %.1f min\n", outcome.rule_95.c_str(),
                  outcome.episodes_to_95, outcome.seconds_to_95 / 60.0);
    }
    std::printf("  policy:     %s\n  checkpoint: %s\n  log:        %s\n  curves:     %s\n", outcome.policy_file.c_str(),
                outcome.checkpoint.c_str(), outcome.log.c_str(), outcome.curves.c_str());
  });
}

}  // namespace autoblock::cli
