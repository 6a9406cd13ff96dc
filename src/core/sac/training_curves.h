// What a training history says: the curves picture (as the paper's figures: the training return
// as a moving average over 10 episodes, and the test return) and how fast training got there.
#pragma once

#include <string>
#include <vector>

#include "core/io/line_chart_svg.h"
#include "core/sac/trainer.h"

namespace autoblock {

struct TrainingSpeed {
  double final_test_return = 0.0;   // mean of the last three evaluations
  double initial_test_return = 0.0; // the first evaluation
  int episodes_to_95 = -1;          // first evaluated episode reaching the 95 % mark (-1: never)
  double seconds_to_95 = -1.0;
  std::string rule;                 // how the 95 % mark was set
};

// Inputs: history. Output: the 95 % mark and when it was first reached. For positive final returns
// the mark is 0.95 x final (as the paper's curves read); otherwise initial + 0.95 (final - initial).
TrainingSpeed training_speed(const std::vector<EpisodeRecord>& history);

// Inputs: history; references, dashed lines on the test panel (e.g. the test set's optimal and
// greedy returns); title. Output: the two-panel SVG.
std::string training_curves_svg(const std::vector<EpisodeRecord>& history, const std::vector<ChartReference>& references,
                                const std::string& title);

// One CSV line per episode: episode, shape, return, blocks, steps, complete, value_loss,
// critic_loss, actor_loss (the lookahead agent's: its proposal actor's, cut_proposer.h), alpha, tau,
// test_return (empty when not evaluated), wall_seconds, proposal_better (the share of the episode's
// turned cuts that beat the listed ones; empty without proposals).
std::string training_csv_header();
std::string training_csv_row(const EpisodeRecord& record);

}  // namespace autoblock
