#include "cli/cli_common.h"

#include <cstdio>

namespace autoblock::cli {

void PolicyArguments::add_to(CLI::App& command) {
  std::string names;
  for (const std::string& name : policy_names()) names += (names.empty() ? "" : " | ") + name;
  command.add_option("--policy", policy, names)->capture_default_str();
  command.add_option("--seed", seed, "seed of the random policies")->capture_default_str();
  command.add_option("--max-steps", max_steps, "step cap per face (0: 10 x corners + 10)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command.add_option("--time-limit", time_limit, "optimal: search seconds per face before finishing greedily")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

std::unique_ptr<Policy> PolicyArguments::make(const InputFace& face, std::uint64_t shape_index) const {
  PolicySettings settings;
  settings.seed = seed + shape_index;
  settings.time_limit = time_limit;
  return make_policy(policy, face.grid, settings);
}

EpisodeOptions PolicyArguments::episode_options() const {
  EpisodeOptions options;
  options.max_steps = max_steps;
  return options;
}

std::string summary_line(const Decomposition& d) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%zu blocks (minimum %d), %zu cuts, return %.3f, %s%s, %.1f ms", d.blocks.size(),
                d.min_blocks, d.cuts.size(), d.total_return, status_name(d.status).c_str(),
                d.time_capped ? " (search time limit hit)" : "", d.seconds * 1000.0);
  return buf;
}

}  // namespace autoblock::cli
