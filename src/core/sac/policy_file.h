// Trained policies and training checkpoints on disk.
//
// A file is a LibTorch archive holding "meta", a JSON text
//   {"format": "autoblock-policy", "version": 1, "kind": "policy" | "checkpoint",
//    "config": <SacConfig>, "training": {...}}
// and the agent's networks (SacAgent::save); a checkpoint adds the target networks, the
// optimisers, the replay buffer ("replay_buffer", bytes) and the trainer's state (in "training").
// Files are written atomically (a temporary file renamed into place).
#pragma once

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/sac/replay_buffer.h"
#include "core/sac/sac_agent.h"

namespace autoblock {

constexpr int kPolicyFormatVersion = 1;

struct LoadedPolicy {
  nlohmann::json meta;
  std::shared_ptr<SacAgent> agent;
  std::unique_ptr<ReplayBuffer> buffer;  // checkpoints only
};

// Inputs: path; agent; training, the trainer's state to store in meta (any JSON); buffer, null for
// a policy, the replay buffer for a checkpoint.
void save_policy_file(const std::string& path, const SacAgent& agent, const nlohmann::json& training,
                      const ReplayBuffer* buffer);

// Inputs: path; checkpoint, true to require and load the training state.
// Output: the agent (and buffer). Throws InputError for a missing, truncated, corrupt or
// incompatible file (wrong format, newer version, unknown network configuration).
LoadedPolicy load_policy_file(const std::string& path, bool checkpoint);

}  // namespace autoblock
