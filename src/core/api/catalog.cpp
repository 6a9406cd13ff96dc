#include "core/api/catalog.h"

#include <algorithm>

#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"

namespace autoblock {

Capabilities capabilities() {
  Capabilities c;
  c.learned_policies = true;
  c.training = true;
  c.vertex_scores = true;
  c.meshing = true;
  return c;
}

std::vector<std::string> policy_names() {
  std::vector<std::string> names{"auto"};
  for (const std::string& name : shipped_policy_names()) names.push_back(name);
  for (const char* name : {"optimal", "greedy", "random-split", "random"}) names.push_back(name);
  return names;
}

std::vector<std::string> general_policy_names() { return {"auto", "search", "greedy", "random"}; }

const std::vector<std::string>& reward_preset_names() {
  static const std::vector<std::string> names{"paper", "mesh"};
  return names;
}

std::string default_reward_preset() { return ""; }

void check_reward_preset(const std::string& name) {
  const auto& names = reward_preset_names();
  if (name.empty() || std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InputError("unknown reward preset '" + name + "' (expected " + list + ")");
}

std::shared_ptr<const PolicySource> policy_source(const std::string& spec, const PolicySettings& settings) {
  BaselineOptions options;
  options.seed = settings.seed;
  options.optimal_seconds = settings.time_limit;
  check_reward_preset(settings.reward);
  options.reward = settings.reward.empty() ? RewardPreset::Paper : reward_preset_by_name(settings.reward);
  return std::make_shared<PolicySource>(spec, options);
}

}  // namespace autoblock
