// What one training episode did, for logs, curves and checkpoints.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "core/env/episode.h"
#include "core/region/region_episode.h"

namespace autoblock {

struct EpisodeRecord {
  int episode = 0;               // 1-based
  std::string shape;
  double ret = 0.0;              // the episode's return (plain sum of the rewards)
  int blocks = 0;
  int steps = 0;
  bool complete = false;
  std::map<std::string, double> metrics;  // means over the episode's updates (empty during warm-up)
  double alpha = 0.0, tau = 0.0;          // the agent's temperatures after the episode
  bool evaluated = false;
  double test_return = 0.0;      // mean deterministic return over the test set, when evaluated
  double wall_seconds = 0.0;     // since training started (a resumed run continues the clock)
};

// Inputs:  episode, as it ended; metric_sums, the metrics of the episode's updates summed by name;
//          updates, how many there were.
// Outputs: the episode's return, blocks, steps, completion and mean metrics (the caller adds the
//          temperatures; the trainer the number, shape, evaluation and clock).
EpisodeRecord episode_record_of(const Episode& episode, const std::map<std::string, double>& metric_sums, int updates);
// The same for an episode on a general face (blocks: its finished parts, templates included).
EpisodeRecord region_episode_record_of(const RegionEpisode& episode, const std::map<std::string, double>& metric_sums,
                                       int updates);

nlohmann::json episode_record_json(const EpisodeRecord& record);
EpisodeRecord episode_record_from_json(const nlohmann::json& json);

}  // namespace autoblock
