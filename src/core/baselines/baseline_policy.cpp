#include "core/baselines/baseline_policy.h"

#include <algorithm>

#include "core/baselines/greedy_policy.h"
#include "core/baselines/optimal_search.h"
#include "core/baselines/random_policy.h"
#include "core/common/error.h"

namespace autoblock {

const std::vector<std::string>& baseline_names() {
  static const std::vector<std::string> names{"random", "random-split", "greedy", "optimal"};
  return names;
}

bool is_baseline_name(const std::string& name) {
  const auto& names = baseline_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::unique_ptr<Policy> make_baseline_policy(const std::string& name, double face_size, const BaselineOptions& options) {
  if (name == "random") return std::make_unique<RandomPolicy>(options.seed, false);
  if (name == "random-split") return std::make_unique<RandomPolicy>(options.seed, true);
  if (name == "greedy") return std::make_unique<GreedyPolicy>();
  if (name == "optimal") return std::make_unique<OptimalPolicy>(face_size, options.optimal_seconds, options.reward);
  throw InputError("unknown policy '" + name + "' (expected random, random-split, greedy or optimal)");
}

}  // namespace autoblock
