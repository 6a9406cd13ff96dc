// Hyper-parameters of the Soft Actor-Critic agent and its training, with their JSON form (stored in
// checkpoints and policy files so that a file always knows how to rebuild its networks).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/env/reward.h"
#include "core/graph/part_graph.h"

namespace autoblock {

// Where the Bellman target's value of a child part comes from (see sac_agent.h).
enum class Bootstrap { Graph, Critics };

struct SacConfig {
  std::string agent = "lookahead";      // "paper" (the paper's SAC) or "lookahead" (learning_agent.h)
  std::string value_network = "small";  // ValueNetworkConfig::by_name: "paper" or "small"
  bool actor_output_relu = false;       // true: a ReLU after the actor's output layer too, as the
                                        // paper's text reads (logits >= 0); its logits die in
                                        // training and the actor stays uniform (sac_agent.h)
  RewardPreset reward = RewardPreset::Paper;
  GraphOptions graph;
  Bootstrap bootstrap = Bootstrap::Graph;
  double gamma = 1.0;                   // discount per level of the tree of parts
  int batch_size = 32;
  int buffer_capacity = 20000;
  int warmup_steps = 200;               // uniformly random cuts before learning starts
  int update_every = 1;                 // environment steps per gradient update
  double lr_value = 1e-3;
  double lr_critic = 1e-3;
  double lr_actor = 1e-3;
  double lr_temperature = 1e-3;
  double lr_final_fraction = 1.0;       // lookahead: the value network's learning rate falls along a
                                        // half cosine to this fraction of lr_value by the last
                                        // episode (1: constant)
  double weight_average_decay = 0.0;    // lookahead: the deployed value network is an exponential
                                        // moving average of the trained one, with this decay per
                                        // update (0: the trained weights themselves)
  int deploy_views = 1;                 // lookahead, deployed: a piece's value is the mean over this
                                        // many of the square's symmetries of it (1 to 8)
  int deploy_top_k = 0;                 // lookahead, deployed: the network values only the pieces of
                                        // the k most promising cuts by a cheap two-step score
                                        // (lookahead_agent.h); 0: every cut (files without it)
  int train_top_k = 12;                 // lookahead, trained on general faces (issue 12): the
                                        // actions of a part are its k candidates with the best
                                        // reward (region_lookahead.h best_candidates); 0: every one
  bool region_taper = false;            // lookahead, general faces, mesh preset: candidates' rewards
                                        // less the search's taper charge (region_reward.h), trained
                                        // and deployed (false: the reward itself; files without it)
  bool region_mask = false;             // paper, trained on general faces: a drawn cut that makes no
                                        // progress is remembered (its reward, its pieces) but not
                                        // made; the agent draws again (up to 8 times), then the
                                        // progress cut is made, as deployed (false: every drawn cut
                                        // is made; files without it)
  int actor_candidates = 0;             // lookahead, general faces: at the vertices of the k best
                                        // candidates by reward (k distinct vertices), an actor on the
                                        // vertex's 9 numbers proposes one more cut each, at an angle
                                        // no fixed list holds (cut_proposer.h); 0: none (files
                                        // without it)
  bool learn_value = true;              // lookahead: false keeps the value network as loaded (no
                                        // value updates), so that a run trains the actor alone
  double polyak = 0.01;                 // paper: target networks move this fraction per update
  int target_update_every = 25;         // lookahead: the target network is copied every so many updates
  double direction_target_entropy = 0.3;     // nats; ln 2 = 0.69 is the maximum for 2 directions
  double angle_target_entropy = -1.0;   // paper, general faces: nats of the squashed angle action u in
                                        // [-1, 1] (continuous_sac_agent.h; -dim(A), SAC's usual choice;
                                        // ln 2 = 0.69 is the uniform's)
  double vertex_target_entropy_fraction = 0.3;  // of ln(number of vertices of the part); lookahead:
                                                // of ln(number of candidate cuts)
  double initial_direction_temperature = 0.2;   // SAC's alpha
  double initial_vertex_temperature = 1.0;      // softmax temperature of the vertex choice
};

// The defaults of an agent kind: "paper" discounts by 0.99 (its sampled cuts include ones that
// change nothing, whose self-loops need a discount), "lookahead" by 1 (the return is a plain sum).
// Throws InputError for an unknown kind.
SacConfig default_sac_config(const std::string& agent);

nlohmann::json sac_config_json(const SacConfig& config);
// Throws InputError for malformed or unknown values, or values out of range (a learning rate,
// temperature, batch size ... that is not positive, a discount or Polyak fraction outside (0, 1]).
SacConfig sac_config_from_json(const nlohmann::json& json);

// Inputs:  config; settings, each "key=value" with key a field of sac_config_json (nested ones as
//          "graph.size_fraction") other than "agent", and value JSON (a number, true/false) or a
//          bare word taken as a string (e.g. "bootstrap=critics").
// Outputs: config with the settings applied, in order (for ablations: `autoblock train --set`).
//          Throws InputError naming the setting when it is malformed, names no such field, or its
//          value has the wrong type or range.
SacConfig with_settings(const SacConfig& config, const std::vector<std::string>& settings);

}  // namespace autoblock
