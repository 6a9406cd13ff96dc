#include "core/sac/policy_source.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/sac/policy_file.h"

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
  return index.value("default", std::string("optimal"));
}

PolicySource::PolicySource(const std::string& name_or_path, BaselineOptions baseline)
    : name_(name_or_path.empty() ? default_policy_name() : name_or_path), baseline_(baseline) {
  if (is_baseline_name(name_)) return;
  std::string path = name_;
  for (const std::string& shipped : shipped_policy_names()) {
    if (shipped == name_) path = (fs::path(models_folder()) / "policies" / (name_ + ".pt")).string();
  }
  std::error_code ec;
  if (path == name_ && !fs::exists(path, ec)) {
    std::string known;
    for (const std::string& n : baseline_names()) known += n + ", ";
    for (const std::string& n : shipped_policy_names()) known += n + ", ";
    throw InputError("unknown policy '" + name_ + "' (expected " + known + "or a policy file)");
  }
  agent_ = load_policy_file(path, false).agent;
}

RewardPreset PolicySource::reward() const { return agent_ ? agent_->config().reward : baseline_.reward; }

std::unique_ptr<Policy> PolicySource::make(double face_size, std::uint64_t seed) const {
  if (agent_) return agent_->deployed_policy(name_);
  BaselineOptions options = baseline_;
  options.seed = seed;
  return make_baseline_policy(name_, face_size, options);
}

}  // namespace autoblock
