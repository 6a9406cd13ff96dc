// Where a decomposition policy comes from: a baseline name, a shipped trained policy's name, or a
// policy file. A trained policy is loaded once, through the learned-policy runtime (loaded on first
// use, learned_runtime.h), and shared by every face it decomposes; a baseline never loads it.
//
// Shipped policies live in the models folder (AUTOBLOCK_MODELS if set, else the checkout's
// models/): models/policies/<name>.pt, listed in models/policies/index.json, whose "default" names
// the policy used when none is asked for.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/baselines/baseline_policy.h"
#include "core/env/policy.h"
#include "core/api/learned_runtime.h"

namespace autoblock {

// The models folder (see above).
std::string models_folder();
// The shipped trained policies' names, from models/policies/index.json (empty when none).
std::vector<std::string> shipped_policy_names();
// The default policy's name: models/policies/index.json's "default", else "auto".
std::string default_policy_name();
// The learned policy "auto" falls back on: index.json's "auto_fallback" (empty when none ships).
std::string auto_fallback_name();

// Inputs: name_or_path, a shipped policy's name or a policy file's path. Output: the file's path.
// Throws InputError for a name that is neither (listing the known names).
std::string policy_file_path(const std::string& name_or_path);

// Writes output, one policy file holding grid's network for faces whose edges run along two
// perpendicular directions and general's for every other face (edges at any angle, arcs): a network
// trained on general faces ships without losing what the grid network knows. grid and general: a
// shipped name or a policy file each (of a two-network file, its own network for that kind).
// Output: the new file's meta (JSON text). Throws InputError (learned_runtime.h, combine_policies).
std::string combine_policies(const std::string& grid, const std::string& general, const std::string& output);

class PolicySource {
 public:
  // Inputs: name_or_path, "auto", a baseline name, a shipped policy name, a policy file's path, or
  //         empty for the default; baseline, options for the baselines (optimal_seconds is every
  //         policy's time limit per face: a learned policy is finished by greedy when it runs out).
  // Throws InputError for an unknown name or a missing, corrupt or incompatible file.
  explicit PolicySource(const std::string& name_or_path, BaselineOptions baseline = {});

  std::string name() const { return name_; }
  bool learned() const { return learned_ != nullptr; }
  bool is_auto() const { return auto_; }
  // The reward preset the policy aims at: a trained policy's own; the baseline option otherwise.
  RewardPreset reward() const;
  // The trained policy (null for a baseline).
  std::shared_ptr<LearnedPolicy> learned_policy() const { return learned_; }
  // The value network that scores vertices: the trained policy's; auto's learned fallback (loaded
  // now); null for a baseline.
  std::shared_ptr<LearnedPolicy> scoring_policy() const;
  // Its name ("sac-mesh" for auto; the policy's own name; empty for a baseline), without loading it.
  std::string scoring_policy_name() const;
  // The policy file's path (empty for a baseline).
  std::string path() const { return path_; }

  // Inputs: face_size (GridFace::size); seed (random baselines). Output: a fresh policy.
  std::unique_ptr<Policy> make(double face_size, std::uint64_t seed) const;

 private:
  std::string name_;
  BaselineOptions baseline_;
  std::string path_;
  std::shared_ptr<LearnedPolicy> learned_;
  bool auto_ = false;
  // auto's learned fallback, loaded on first need (shared by every face, thread-safe).
  std::unique_ptr<Policy> make_auto_fallback() const;
  std::shared_ptr<const PolicySource> auto_fallback() const;
  mutable std::mutex fallback_mutex_;
  mutable std::shared_ptr<const PolicySource> fallback_;
};

}  // namespace autoblock
