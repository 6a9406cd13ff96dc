#include "core/sac/sac_config.h"

#include "core/common/error.h"

namespace autoblock {

SacConfig default_sac_config(const std::string& agent) {
  SacConfig config;
  config.agent = agent;
  if (agent == "paper") {
    config.gamma = 0.99;
  } else if (agent == "lookahead") {
    // Measured on fresh validation faces (BENCHMARKS.md): deploying the weights' moving average and
    // averaging two symmetric views each add about half a point of the optimal return.
    config.weight_average_decay = 0.998;
    config.deploy_views = 2;
    // Measured on validation faces (BENCHMARKS.md, issue 8): the network values the pieces of the 6
    // best cuts by the two-step score (lookahead_agent.h), about half the graphs on 2-10 rectangle
    // faces and a fifth on 11-40; the smallest k at which both rewards' policies keep their quality
    // targets (with 3, Eq. (1)'s loses about 2 points of the optimal return on 11-40 faces).
    config.deploy_top_k = 6;
  } else {
    throw InputError("unknown agent '" + agent + "' (expected paper or lookahead)");
  }
  return config;
}

namespace {

// Throws InputError naming the first field out of its range.
void check_ranges(const SacConfig& c) {
  auto require = [](bool ok, const char* key, const char* range) {
    if (!ok) throw InputError(std::string(key) + " must be " + range);
  };
  require(c.gamma > 0.0 && c.gamma <= 1.0, "gamma", "in (0, 1]");
  require(c.batch_size >= 1, "batch_size", ">= 1");
  require(c.buffer_capacity >= 1, "buffer_capacity", ">= 1");
  require(c.warmup_steps >= 0, "warmup_steps", ">= 0");
  require(c.update_every >= 1, "update_every", ">= 1");
  require(c.lr_value > 0.0, "lr_value", "> 0");
  require(c.lr_critic > 0.0, "lr_critic", "> 0");
  require(c.lr_actor > 0.0, "lr_actor", "> 0");
  require(c.lr_temperature > 0.0, "lr_temperature", "> 0");
  require(c.polyak > 0.0 && c.polyak <= 1.0, "polyak", "in (0, 1]");
  require(c.target_update_every >= 1, "target_update_every", ">= 1");
  require(c.direction_target_entropy >= 0.0, "direction_target_entropy", ">= 0");
  require(c.vertex_target_entropy_fraction >= 0.0, "vertex_target_entropy_fraction", ">= 0");
  require(c.initial_direction_temperature > 0.0, "initial_direction_temperature", "> 0");
  require(c.initial_vertex_temperature > 0.0, "initial_vertex_temperature", "> 0");
  require(c.graph.size_fraction > 0.0, "graph.size_fraction", "> 0");
  require(c.graph.shape_bound > 0.0, "graph.shape_bound", "> 0");
}

}  // namespace

nlohmann::json sac_config_json(const SacConfig& c) {
  return {{"agent", c.agent},
          {"value_network", c.value_network},
          {"actor_output_relu", c.actor_output_relu},
          {"reward", reward_preset_name(c.reward)},
          {"graph",
           {{"size_fraction", c.graph.size_fraction},
            {"shape_bound", c.graph.shape_bound},
            {"method", graph_method_name(c.graph.method)}}},
          {"bootstrap", c.bootstrap == Bootstrap::Graph ? "graph" : "critics"},
          {"gamma", c.gamma},
          {"batch_size", c.batch_size},
          {"buffer_capacity", c.buffer_capacity},
          {"warmup_steps", c.warmup_steps},
          {"update_every", c.update_every},
          {"lr_value", c.lr_value},
          {"lr_critic", c.lr_critic},
          {"lr_actor", c.lr_actor},
          {"lr_temperature", c.lr_temperature},
          {"lr_final_fraction", c.lr_final_fraction},
          {"weight_average_decay", c.weight_average_decay},
          {"deploy_views", c.deploy_views},
          {"deploy_top_k", c.deploy_top_k},
          {"train_top_k", c.train_top_k},
          {"region_taper", c.region_taper},
          {"region_mask", c.region_mask},
          {"actor_candidates", c.actor_candidates},
          {"learn_value", c.learn_value},
          {"polyak", c.polyak},
          {"target_update_every", c.target_update_every},
          {"direction_target_entropy", c.direction_target_entropy},
          {"angle_target_entropy", c.angle_target_entropy},
          {"vertex_target_entropy_fraction", c.vertex_target_entropy_fraction},
          {"initial_direction_temperature", c.initial_direction_temperature},
          {"initial_vertex_temperature", c.initial_vertex_temperature}};
}

SacConfig sac_config_from_json(const nlohmann::json& j) {
  try {
    SacConfig c;
    c.agent = j.at("agent").get<std::string>();
    if (c.agent != "paper" && c.agent != "lookahead") throw InputError("unknown agent '" + c.agent + "'");
    c.value_network = j.at("value_network").get<std::string>();
    c.actor_output_relu = j.at("actor_output_relu").get<bool>();
    c.reward = reward_preset_by_name(j.at("reward").get<std::string>());
    c.graph.size_fraction = j.at("graph").at("size_fraction").get<double>();
    c.graph.shape_bound = j.at("graph").at("shape_bound").get<double>();
    // Files written before issue 8 name no method: their networks learned on refined graphs.
    c.graph.method = graph_method_by_name(j.at("graph").value("method", std::string("refined")));
    const std::string bootstrap = j.at("bootstrap").get<std::string>();
    if (bootstrap != "graph" && bootstrap != "critics") throw InputError("unknown bootstrap '" + bootstrap + "'");
    c.bootstrap = bootstrap == "graph" ? Bootstrap::Graph : Bootstrap::Critics;
    c.gamma = j.at("gamma").get<double>();
    c.batch_size = j.at("batch_size").get<int>();
    c.buffer_capacity = j.at("buffer_capacity").get<int>();
    c.warmup_steps = j.at("warmup_steps").get<int>();
    c.update_every = j.at("update_every").get<int>();
    c.lr_value = j.at("lr_value").get<double>();
    c.lr_critic = j.at("lr_critic").get<double>();
    c.lr_actor = j.at("lr_actor").get<double>();
    c.lr_temperature = j.at("lr_temperature").get<double>();
    c.lr_final_fraction = j.value("lr_final_fraction", 1.0);  // files written before the schedule: constant
    if (!(c.lr_final_fraction > 0.0 && c.lr_final_fraction <= 1.0)) throw InputError("lr_final_fraction must be in (0, 1]");
    c.weight_average_decay = j.value("weight_average_decay", 0.0);  // likewise: no averaging
    if (!(c.weight_average_decay >= 0.0 && c.weight_average_decay < 1.0)) throw InputError("weight_average_decay must be in [0, 1)");
    c.deploy_views = j.value("deploy_views", 1);
    if (c.deploy_views < 1 || c.deploy_views > 8) throw InputError("deploy_views must be in 1..8");
    c.deploy_top_k = j.value("deploy_top_k", 0);  // files written before it: every cut is valued
    if (c.deploy_top_k < 0) throw InputError("deploy_top_k must be >= 0");
    c.train_top_k = j.value("train_top_k", 12);  // files written before it learned on grid faces only
    if (c.train_top_k < 0) throw InputError("train_top_k must be >= 0");
    c.region_taper = j.value("region_taper", false);
    c.region_mask = j.value("region_mask", false);
    c.actor_candidates = j.value("actor_candidates", 0);  // files before the proposals: none
    if (c.actor_candidates < 0 || c.actor_candidates > 8) throw InputError("actor_candidates must be in 0..8");
    c.learn_value = j.value("learn_value", true);
    c.polyak = j.at("polyak").get<double>();
    c.target_update_every = j.at("target_update_every").get<int>();
    c.direction_target_entropy = j.at("direction_target_entropy").get<double>();
    c.angle_target_entropy = j.value("angle_target_entropy", -1.0);  // files before the continuous agent
    c.vertex_target_entropy_fraction = j.at("vertex_target_entropy_fraction").get<double>();
    c.initial_direction_temperature = j.at("initial_direction_temperature").get<double>();
    c.initial_vertex_temperature = j.at("initial_vertex_temperature").get<double>();
    check_ranges(c);
    return c;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("malformed agent configuration: ") + e.what());
  }
}


SacConfig with_settings(const SacConfig& config, const std::vector<std::string>& settings) {
  nlohmann::json j = sac_config_json(config);
  for (const std::string& setting : settings) {
    const size_t eq = setting.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == setting.size()) {
      throw InputError("setting '" + setting + "': expected key=value");
    }
    const std::string key = setting.substr(0, eq), text = setting.substr(eq + 1);
    nlohmann::json* slot = &j;
    std::string rest = key;
    for (size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1)) {
      slot = slot->contains(rest.substr(0, dot)) ? &(*slot)[rest.substr(0, dot)] : nullptr;
      if (!slot || !slot->is_object()) break;
    }
    if (key == "agent" || !slot || !slot->is_object() || !slot->contains(rest) || (*slot)[rest].is_object()) {
      throw InputError("setting '" + setting + "': no configuration field '" + key + "'");
    }
    nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    if (value.is_discarded()) value = text;  // a bare word: a string
    (*slot)[rest] = value;
    try {
      sac_config_from_json(j);
    } catch (const InputError& e) {
      throw InputError("setting '" + setting + "': " + e.what());
    }
  }
  return sac_config_from_json(j);
}

}  // namespace autoblock
