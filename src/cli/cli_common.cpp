#include "cli/cli_common.h"

#include <cstdio>
#include <filesystem>
#include <map>

#include "core/common/error.h"
#include "core/common/format.h"

namespace autoblock::cli {

void PolicyArguments::add_to(CLI::App& command) {
  command.add_option("--policy", policy,
                     "auto (exact search, learned where it runs out of time) | random | random-split | greedy | optimal | a shipped policy (sac-paper, sac-mesh, sac-faithful) | a policy file "
                     "(default: the shipped default, " + default_policy_name() + "); on faces with edges at other angles: auto or search (lookahead search), greedy, random");
  command.add_option("--seed", seed, "seed of the random policies")->capture_default_str();
  command.add_option("--max-steps", max_steps, "step cap per face (0: 10 x corners + 10)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  time_limit_option_ = command.add_option("--time-limit", time_limit, "seconds per face before greedy finishes the remaining parts (optimal, auto and learned policies; on faces with edges at other angles, the search's and a learned policy's budget, default 2); the searches' budgets (optimal's, auto's exact search, the general search) and a learned policy's on general faces are counted in work, about that many seconds, so a face decomposes the same on any machine")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--reward", reward, "reward preset: paper (Eq. 1) | mesh (few, fat blocks); default: the policy's own")
      ->check(CLI::IsMember({"paper", "mesh"}));
}

std::shared_ptr<const PolicySource> PolicyArguments::source() const {
  if (!source_) {
    BaselineOptions options;
    options.optimal_seconds = time_limit;
    options.reward = reward.empty() ? RewardPreset::Paper : reward_preset_by_name(reward);  // optimal's target
    source_ = std::make_shared<PolicySource>(policy, options);
  }
  return source_;
}

std::unique_ptr<Policy> PolicyArguments::make(const InputFace& face, std::uint64_t shape_index) const {
  return source()->make(face.grid.size, seed + shape_index);
}

PolicySettings PolicyArguments::policy_settings(std::uint64_t shape_index) const {
  PolicySettings settings;
  settings.seed = seed + shape_index;
  settings.time_limit = time_limit;
  settings.reward = reward;
  if (time_limit_option_ && time_limit_option_->count() > 0) settings.general_time_limit = time_limit;
  return settings;
}

DecomposeSettings PolicyArguments::decompose_settings(std::uint64_t shape_index) const {
  DecomposeSettings settings;
  settings.policy = policy;
  settings.reward = reward;
  settings.policy_settings = policy_settings(shape_index);
  settings.max_steps = max_steps;
  settings.occt_blocks = false;
  return settings;
}

EpisodeOptions PolicyArguments::episode_options() const {
  EpisodeOptions options;
  options.max_steps = max_steps;
  options.reward = reward.empty() ? source()->reward() : reward_preset_by_name(reward);
  return options;
}

void FaceArguments::add_to(CLI::App& command) {
  command.add_option("--face", face,
                     "the face to use when the file holds several (a solid, a shell): its number N, as FreeCAD "
                     "numbers faces (Face1, Face2, ...); `autoblock faces FILE` lists them")
      ->check(CLI::Validator(
          [](std::string& text) {
            int n = 0;
            return CLI::detail::lexical_cast(text, n) && n >= 1
                       ? std::string()
                       : "faces are numbered from 1 (Face1, Face2, ...), not " + text;
          },
          "N >= 1"));
}

std::string FaceArguments::how_to_choose(const std::string& file) const {
  return "choose one with --face N (`autoblock faces " + file + "` lists them)";
}

InputFace FaceArguments::load(const std::string& file) const { return load_input_face(file, face, how_to_choose(file)); }

void require_extension(const std::string& path, const std::vector<std::string>& allowed, const std::string& option) {
  if (path.empty()) return;
  const std::string ext = std::filesystem::path(path).extension().string();
  for (const std::string& a : allowed) {
    if (ext == a) return;
  }
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw InputError(option + " " + path + ": expected a " + list + " file");
}


std::string summary_line(const Decomposition& d) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s (minimum %d), %s, return %.3f, %s%s, %.1f ms",
                counted(static_cast<long long>(d.blocks.size()), "block").c_str(), d.min_blocks,
                counted(static_cast<long long>(d.cuts.size()), "cut").c_str(), d.total_return,
                status_name(d.status).c_str(), d.time_capped ? " (time limit hit: greedy finished)" : "",
                d.seconds * 1000.0);
  // Who decided the cuts, when that is not simply the policy itself (auto, a time limit).
  std::map<std::string, int> deciders;
  for (const std::string& who : d.decided_by) ++deciders[who];
  if (deciders.empty() || (deciders.size() == 1 && deciders.begin()->first == d.policy)) return buf;
  std::string out = std::string(buf) + ", cuts by";
  for (const auto& [who, count] : deciders) out += " " + who + " " + std::to_string(count) + ",";
  out.pop_back();
  return out;
}

}  // namespace autoblock::cli
