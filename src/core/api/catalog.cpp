#include "core/api/catalog.h"

#include <algorithm>

#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"

namespace autoblock {

Capabilities capabilities() { return Capabilities{}; }

const std::vector<std::string>& policy_names() {
  static const std::vector<std::string> names{"optimal", "greedy", "random-split", "random"};
  return names;
}

std::string default_policy_name() { return "optimal"; }

const std::vector<std::string>& reward_preset_names() {
  static const std::vector<std::string> names{"paper"};
  return names;
}

std::string default_reward_preset() { return "paper"; }

void check_reward_preset(const std::string& name) {
  const auto& names = reward_preset_names();
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InputError("unknown reward preset '" + name + "' (expected " + list + ")");
}

std::unique_ptr<Policy> make_policy(const std::string& spec, const GridFace& face, const PolicySettings& settings) {
  if (is_baseline_name(spec)) {
    BaselineOptions options;
    options.seed = settings.seed;
    options.optimal_seconds = settings.time_limit;
    return make_baseline_policy(spec, face.size, options);
  }
  std::string list;
  for (const std::string& n : policy_names()) list += (list.empty() ? "" : ", ") + n;
  if (spec.find('/') != std::string::npos || spec.find('.') != std::string::npos) {
    throw InputError("policy file '" + spec + "': this build has no learned policies, so it cannot load policy "
                     "files (available: " + list + ")");
  }
  throw InputError("unknown policy '" + spec + "' (expected " + list + ")");
}

}  // namespace autoblock
