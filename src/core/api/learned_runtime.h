// The learned-policy runtime, loaded on first use.
//
// Everything that needs LibTorch (the networks, the agents, policy files, training) lives in the
// shared library libautoblock_learn.so, which no front end links: LibTorch's static initialisation
// alone costs about 0.8 s per process (platform notes), so a command or a FreeCAD session that uses
// no network must not pay it. The first call of learned_runtime() loads the library (common/plugin.h)
// from $AUTOBLOCK_LEARN_LIBRARY if set, else from the folder libautoblock_core.so was loaded from.
//
// Inputs/outputs: the interfaces below, with only core types in their signatures.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/api/training_job.h"
#include "core/env/episode.h"
#include "core/env/policy.h"
#include "core/env/reward.h"
#include "core/region/region_policy.h"

namespace autoblock {

// A trained policy, loaded from a policy file; shared by every face it decomposes.
class LearnedPolicy {
 public:
  virtual ~LearnedPolicy() = default;
  // The reward preset it was trained with.
  virtual RewardPreset reward() const = 0;
  // Inputs: name, for reports. Output: the deterministic deployed policy (sharing this one).
  virtual std::unique_ptr<Policy> deployed_policy(const std::string& name) = 0;
  // The value network's score at every model vertex of the episode's current part.
  virtual std::vector<float> vertex_scores(const Episode& episode) = 0;
  // Inputs: name, for reports. Output: the deployed policy on general faces (the lookahead agent's,
  //         sac/region_lookahead_policy.h), or null when the agent has none (the paper's agent).
  //         The caller holds lock_general_engine() while it runs, as for any policy on regions.
  virtual std::unique_ptr<RegionPolicy> deployed_region_policy(const std::string& name) = 0;
  // The same as vertex_scores on a general face's episode (RegionLookaheadPolicy::vertex_scores); the
  // caller holds lock_general_engine(). Throws InputError when the agent has no policy on them.
  virtual std::vector<float> region_vertex_scores(const RegionEpisode& episode) = 0;
  // True when the file holds a second network for general faces (policy file version 2).
  virtual bool general_network() const = 0;
};

class LearnedRuntime {
 public:
  virtual ~LearnedRuntime() = default;
  // Inputs: path, a policy file. Throws InputError for a missing, corrupt or incompatible file.
  virtual std::shared_ptr<LearnedPolicy> load_policy(const std::string& path) = 0;
  // Writes output, a policy file with grid's network for rectilinear faces and general's for the
  // others (sac/policy_file.h, combine_policy_files); grid and general are policy files' paths.
  // Output: the new file's meta (JSON text). Throws InputError for unreadable files, different
  // reward presets, a general network without a policy on general faces, or a missing folder.
  virtual std::string combine_policies(const std::string& grid, const std::string& general,
                                       const std::string& output) = 0;
  // See run_training_job (training_job.h).
  virtual TrainingOutcome run_training_job(const TrainingJob& job, const TrainingCallbacks& callbacks) = 0;
};

// Output: the runtime, loaded on the first call (thread-safe). Throws std::runtime_error naming the
// library and dlopen's message when it cannot be loaded.
LearnedRuntime& learned_runtime();

// True once the runtime has been loaded in this process (for tests and reports; never loads it).
bool learned_runtime_loaded();

}  // namespace autoblock

// The library's one exported entry point (a function, not an object, so that its construction
// happens on first call).
extern "C" autoblock::LearnedRuntime* autoblock_learned_runtime();
