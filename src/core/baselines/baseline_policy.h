// The baseline policies by name, for the CLI, the bindings and evaluation.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/env/policy.h"
#include "core/env/reward.h"

namespace autoblock {

struct BaselineOptions {
  std::uint64_t seed = 0;          // random and random-split
  double optimal_seconds = 30.0;   // optimal: time budget per face (<= 0: unlimited)
  RewardPreset reward = RewardPreset::Paper;  // optimal: the reward it maximises (greedy uses the episode's)
};

// The names: "random", "random-split", "greedy", "optimal".
const std::vector<std::string>& baseline_names();
bool is_baseline_name(const std::string& name);

// Inputs:  name, one of baseline_names(); face_size (the reward scale, GridFace::size); options.
// Outputs: a new policy. Throws InputError for an unknown name.
std::unique_ptr<Policy> make_baseline_policy(const std::string& name, double face_size, const BaselineOptions& options);

}  // namespace autoblock
