// Trained policies and training checkpoints on disk.
//
// A file is a LibTorch archive holding "meta", a JSON text
//   {"format": "autoblock-policy", "version": 1 | 2, "kind": "policy" | "checkpoint",
//    "config": <SacConfig>, "training": {...}, "general": {"config", "training"} (version 2 only)}
// and the agent's networks (LearningAgent::save); a checkpoint adds the target networks, the
// optimisers, the replay memory ("replay_memory", bytes) and the trainer's state (in "training").
// Version 2 (issue 12) is a policy with a second agent for general faces (edges at any angle, arcs):
// its networks in the sub-archive "general", its configuration and training under meta's "general".
// The first agent then decides on rectilinear faces only. A file without a second agent is written
// as version 1, which every earlier build reads. Files are written atomically (a temporary file
// renamed into place).
#pragma once

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/sac/learning_agent.h"

namespace autoblock {

constexpr int kPolicyFormatVersion = 2;

struct LoadedPolicy {
  nlohmann::json meta;
  std::shared_ptr<LearningAgent> agent;  // with its training state and replay memory for checkpoints
  std::shared_ptr<LearningAgent> general;  // the agent for general faces (version 2), else null
  // The agent that decides on general faces: general if present, else agent.
  std::shared_ptr<LearningAgent> general_agent() const { return general ? general : agent; }
};

// Inputs: path; agent; training, the trainer's state to store in meta (any JSON); checkpoint, true
// to include the agent's training state and replay memory.
void save_policy_file(const std::string& path, const LearningAgent& agent, const nlohmann::json& training,
                      bool checkpoint);

// A policy file with two agents (version 2): grid's for rectilinear faces, general's for the others.
// Inputs: path; grid and general with the meta "training" each recorded. Output: the meta written.
// Throws InputError when the two aim at different reward presets or general has no policy on general faces.
nlohmann::json save_two_agent_policy_file(const std::string& path, const LearningAgent& grid, const nlohmann::json& grid_training,
                                const std::shared_ptr<LearningAgent>& general, const nlohmann::json& general_training);

// Inputs: grid_source, general_source, policy files (the first's rectilinear agent, the second's agent
// for general faces are taken); path, the file to write. Output: the written file's meta. Throws
// InputError as load_policy_file and save_two_agent_policy_file do.
nlohmann::json combine_policy_files(const std::string& grid_source, const std::string& general_source,
                                    const std::string& path);

// Inputs: path; checkpoint, true to require and load the training state.
// Output: the agent. Throws InputError for a missing, truncated, corrupt or incompatible file
// (wrong format, newer version, unknown network configuration).
LoadedPolicy load_policy_file(const std::string& path, bool checkpoint);

}  // namespace autoblock
