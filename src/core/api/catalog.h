// What the front ends (CLI, Python binding, FreeCAD workbench) offer the user: the shipped
// policies, the reward presets, the default of each, and what this build can do. The front ends
// take these lists from here, never from their own copies.
//
// Policies come from api/policy_source.h: the baselines, the shipped trained policies and policy
// files.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/env/policy.h"
#include "core/geometry/grid_face.h"
#include "core/api/policy_source.h"

namespace autoblock {

// What this build can do beyond the baselines.
struct Capabilities {
  bool learned_policies = false;  // policy files and shipped learned policies
  bool training = false;          // training a policy
  bool vertex_scores = false;     // per-vertex value-network scores (a learned policy's)
  bool meshing = false;           // conformal merge and quad meshing of the blocks
};
Capabilities capabilities();

// The policy names front ends list: "auto" (the exact search where it finishes in time, a learned
// policy where it does not: baselines/auto_policy.h), the shipped trained policies, then the
// baselines. The default (default_policy_name(), api/policy_source.h) is one of them.
std::vector<std::string> policy_names();

// The policies of the general engine (faces with edges at any angle, core/region): "auto" and
// "search" (the lookahead search, region_search.h; also what "optimal" means there), "greedy", "random"
// (and "random-split", the same there). Learned policies work on rectilinear faces only (issue 12).
// Their own reward preset (used without --reward): mesh for auto and search, paper for the others.
std::vector<std::string> general_policy_names();

// The reward presets: "paper" (Eq. 1) and "mesh". The default is "": each policy's own preset.
const std::vector<std::string>& reward_preset_names();
std::string default_reward_preset();
// Throws InputError unless name is empty or one of reward_preset_names().
void check_reward_preset(const std::string& name);

struct PolicySettings {
  std::uint64_t seed = 0;     // random policies
  double time_limit = 30.0;   // seconds per face (<= 0: unlimited): optimal finishes greedily after it, and so
                              // do auto and learned policies
  std::string reward;         // the preset optimal maximises (a name of reward_preset_names(); empty: paper)
  double general_time_limit = 2.0;  // seconds per face (<= 0: unlimited) for the general engine's search
                                    // (auto, search), after which progress cuts finish the parts, and for
                                    // a learned policy on a general face (then greedy finishes them)
  int general_search_width = 0;     // the general search's candidates expanded per part (0: its default)
  bool general_divide_holes = true;  // the general search divides a part with many holes along its ligaments
                                     // before searching it (hole_division.h)
  bool general_tight_ogrid = true;   // the general search may finish a tight cell with its O-grid (block.h)
};

// Inputs:  spec, a name of policy_names() or a policy file's path (empty: the default); settings.
// Outputs: where the policy comes from (a trained policy is loaded once). Throws InputError for an
//          unknown name or a bad policy file.
std::shared_ptr<const PolicySource> policy_source(const std::string& spec, const PolicySettings& settings);

}  // namespace autoblock
