// Trained policies and training checkpoints on disk.
//
// A file is a LibTorch archive holding "meta", a JSON text
//   {"format": "autoblock-policy", "version": 1, "kind": "policy" | "checkpoint",
//    "config": <SacConfig>, "training": {...}}
// and the agent's networks (LearningAgent::save); a checkpoint adds the target networks, the
// optimisers, the replay memory ("replay_memory", bytes) and the trainer's state (in "training").
// Files are written atomically (a temporary file renamed into place).
#pragma once

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/sac/learning_agent.h"

namespace autoblock {

constexpr int kPolicyFormatVersion = 1;

struct LoadedPolicy {
  nlohmann::json meta;
  std::shared_ptr<LearningAgent> agent;  // with its training state and replay memory for checkpoints
};

// Inputs: path; agent; training, the trainer's state to store in meta (any JSON); checkpoint, true
// to include the agent's training state and replay memory.
void save_policy_file(const std::string& path, const LearningAgent& agent, const nlohmann::json& training,
                      bool checkpoint);

// Inputs: path; checkpoint, true to require and load the training state.
// Output: the agent. Throws InputError for a missing, truncated, corrupt or incompatible file
// (wrong format, newer version, unknown network configuration).
LoadedPolicy load_policy_file(const std::string& path, bool checkpoint);

}  // namespace autoblock
