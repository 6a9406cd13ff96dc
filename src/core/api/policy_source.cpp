#include "core/api/policy_source.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/baselines/auto_policy.h"
#include "core/common/error.h"

#ifndef AUTOBLOCK_SOURCE_MODELS
#define AUTOBLOCK_SOURCE_MODELS "models"
#endif

namespace autoblock {
namespace {

namespace fs = std::filesystem;

nlohmann::json policy_index() {
  const fs::path index = fs::path(models_folder()) / "policies" / "index.json";
  std::ifstream in(index);
  if (!in) return nlohmann::json::object();
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    throw InputError(index.string() + ": malformed policy index");
  }
}

}  // namespace

std::string models_folder() {
  if (const char* env = std::getenv("AUTOBLOCK_MODELS"); env && *env) return env;
  return AUTOBLOCK_SOURCE_MODELS;
}

std::vector<std::string> shipped_policy_names() {
  std::vector<std::string> names;
  const nlohmann::json index = policy_index();
  if (index.contains("policies")) {
    for (const auto& [name, info] : index["policies"].items()) names.push_back(name);
  }
  return names;
}

std::string default_policy_name() {
  const nlohmann::json index = policy_index();
  return index.value("default", std::string("auto"));
}

std::string auto_fallback_name() {
  const nlohmann::json index = policy_index();
  const std::string name = index.value("auto_fallback", std::string());
  for (const std::string& shipped : shipped_policy_names()) {
    if (shipped == name) return name;
  }
  return "";
}

std::string combine_policies(const std::string& grid, const std::string& general, const std::string& output) {
  if (output.empty()) throw InputError("no output file for the combined policy");
  return learned_runtime().combine_policies(policy_file_path(grid), policy_file_path(general), output);
}

PolicySource::PolicySource(const std::string& name_or_path, BaselineOptions baseline)
    : name_(name_or_path.empty() ? default_policy_name() : name_or_path), baseline_(baseline) {
  if (name_ == "auto") {
    auto_ = true;
    return;
  }
  if (is_baseline_name(name_)) return;
  path_ = policy_file_path(name_);
  learned_ = learned_runtime().load_policy(path_);
}

std::string policy_file_path(const std::string& name_or_path) {
  for (const std::string& shipped : shipped_policy_names()) {
    if (shipped == name_or_path) return (fs::path(models_folder()) / "policies" / (name_or_path + ".pt")).string();
  }
  std::error_code ec;
  if (!fs::exists(name_or_path, ec)) {
    std::string known = "auto, ";
    for (const std::string& n : baseline_names()) known += n + ", ";
    for (const std::string& n : shipped_policy_names()) known += n + ", ";
    throw InputError("unknown policy '" + name_or_path + "' (expected " + known + "or a policy file)");
  }
  return name_or_path;
}

RewardPreset PolicySource::reward() const {
  if (auto_) return RewardPreset::Mesh;
  return learned_ ? learned_->reward() : baseline_.reward;
}

std::shared_ptr<const PolicySource> PolicySource::auto_fallback() const {
  std::lock_guard<std::mutex> lock(fallback_mutex_);
  if (!fallback_) {
    const std::string name = auto_fallback_name();
    if (name.empty()) throw InputError("no learned policy ships for auto to fall back on");
    fallback_ = std::make_shared<PolicySource>(name, BaselineOptions{});
  }
  return fallback_;
}

std::unique_ptr<Policy> PolicySource::make_auto_fallback() const {
  const auto fallback = auto_fallback();
  return fallback->learned_policy()->deployed_policy(fallback->name());
}

std::string PolicySource::scoring_policy_name() const {
  if (auto_) return auto_fallback_name();
  return learned_ ? name_ : std::string();
}

std::shared_ptr<LearnedPolicy> PolicySource::scoring_policy() const {
  if (auto_) return auto_fallback()->learned_policy();
  return learned_;
}

std::unique_ptr<Policy> PolicySource::make(double face_size, std::uint64_t seed) const {
  if (auto_) {
    AutoPolicyOptions options;
    options.total_seconds = baseline_.optimal_seconds;
    return std::make_unique<AutoPolicy>(face_size, options, [this] { return make_auto_fallback(); });
  }
  if (learned_) return time_limited(learned_->deployed_policy(name_), baseline_.optimal_seconds);
  BaselineOptions options = baseline_;
  options.seed = seed;
  return make_baseline_policy(name_, face_size, options);
}

}  // namespace autoblock
