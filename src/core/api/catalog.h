// What the front ends (CLI, Python binding, FreeCAD workbench) offer the user: the shipped
// policies, the reward presets, the default of each, and what this build can do. The front ends
// take these lists from here, never from their own copies.
//
// The learning issue extends policy_names() with the shipped learned policies ("sac-paper", ...),
// lets make_policy() load policy files, adds reward presets and sets the capability flags; the
// meshing issue sets `meshing`.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/env/policy.h"
#include "core/geometry/grid_face.h"

namespace autoblock {

// What this build can do beyond the baselines.
struct Capabilities {
  bool learned_policies = false;  // policy files and shipped learned policies
  bool training = false;          // training a policy
  bool vertex_scores = false;     // per-vertex value-network scores (a learned policy's)
  bool meshing = false;           // conformal merge and quad meshing of the blocks
};
Capabilities capabilities();

// The policy names front ends list, default first among equals: baselines now.
const std::vector<std::string>& policy_names();
// The policy used when the user names none: "optimal" (the best baseline) until a learned policy ships.
std::string default_policy_name();

// The reward presets: "paper" (Eq. 1).
const std::vector<std::string>& reward_preset_names();
std::string default_reward_preset();
// Throws InputError unless name is one of reward_preset_names().
void check_reward_preset(const std::string& name);

struct PolicySettings {
  std::uint64_t seed = 0;     // random policies
  double time_limit = 30.0;   // optimal: search seconds per face (<= 0: unlimited)
};

// Inputs:  spec, a name of policy_names() or a policy file's path; face, the face it will run on
//          (the reward scale); settings.
// Outputs: the policy. Throws InputError for an unknown name, and for a file while this build has
//          no learned policies (saying so).
std::unique_ptr<Policy> make_policy(const std::string& spec, const GridFace& face, const PolicySettings& settings);

}  // namespace autoblock
