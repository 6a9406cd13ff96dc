// Where a decomposition policy comes from: a baseline name, a shipped trained policy's name, or a
// policy file. A trained policy is loaded once and shared by every face it decomposes.
//
// Shipped policies live in the models folder (AUTOBLOCK_MODELS if set, else the checkout's
// models/): models/policies/<name>.pt, listed in models/policies/index.json, whose "default" names
// the policy used when none is asked for.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/baselines/baseline_policy.h"
#include "core/env/policy.h"
#include "core/sac/learning_agent.h"

namespace autoblock {

// The models folder (see above).
std::string models_folder();
// The shipped trained policies' names, from models/policies/index.json (empty when none).
std::vector<std::string> shipped_policy_names();
// The shipped default policy's name ("optimal" when no trained policy ships).
std::string default_policy_name();

class PolicySource {
 public:
  // Inputs: name_or_path, a baseline name, a shipped policy name, a policy file's path, or empty
  //         for the shipped default; baseline, options for the baselines.
  // Throws InputError for an unknown name or a missing, corrupt or incompatible file.
  explicit PolicySource(const std::string& name_or_path, BaselineOptions baseline = {});

  std::string name() const { return name_; }
  bool learned() const { return agent_ != nullptr; }
  // The reward preset the policy aims at: a trained policy's own; the baseline option otherwise.
  RewardPreset reward() const;
  std::shared_ptr<LearningAgent> agent() const { return agent_; }

  // Inputs: face_size (GridFace::size); seed (random baselines). Output: a fresh policy.
  std::unique_ptr<Policy> make(double face_size, std::uint64_t seed) const;

 private:
  std::string name_;
  BaselineOptions baseline_;
  std::shared_ptr<LearningAgent> agent_;
};

}  // namespace autoblock
