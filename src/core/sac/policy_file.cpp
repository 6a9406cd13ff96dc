#include "core/sac/policy_file.h"

#include <cstring>
#include <filesystem>

#include "core/common/error.h"
#include "core/io/atomic_file.h"
#include "core/region/region_policy.h"
#include <torch/torch.h>

namespace autoblock {

namespace fs = std::filesystem;

namespace {

void write_archive(const std::string& path, torch::serialize::OutputArchive& archive) {
  write_file_atomically(path, [&](const std::string& temporary) {
    try {
      archive.save_to(temporary);
      return true;
    } catch (const c10::Error&) {
      return false;
    }
  });
}

// The header every policy file starts with: format, version, kind, the agent's configuration (so the
// file rebuilds its networks) and the training summary.
nlohmann::json policy_meta(int version, bool checkpoint, const LearningAgent& agent, const nlohmann::json& training) {
  return {{"format", "autoblock-policy"},
          {"version", version},
          {"kind", checkpoint ? "checkpoint" : "policy"},
          {"config", sac_config_json(agent.config())},
          {"training", training}};
}

}  // namespace

void save_policy_file(const std::string& path, const LearningAgent& agent, const nlohmann::json& training,
                      bool checkpoint) {
  const nlohmann::json meta = policy_meta(1, checkpoint, agent, training);
  torch::serialize::OutputArchive archive;
  archive.write("meta", c10::IValue(meta.dump()));
  agent.save(archive, checkpoint);
  if (checkpoint) {
    const std::string bytes = agent.serialize_memory();
    torch::Tensor blob = torch::empty({static_cast<int64_t>(bytes.size())}, torch::kUInt8);
    std::memcpy(blob.data_ptr<uint8_t>(), bytes.data(), bytes.size());
    archive.write("replay_memory", blob);
  }
  write_archive(path, archive);
}

nlohmann::json save_two_agent_policy_file(const std::string& path, const LearningAgent& grid, const nlohmann::json& grid_training,
                                const std::shared_ptr<LearningAgent>& general, const nlohmann::json& general_training) {
  if (!general) throw InputError("no network for general faces");
  if (grid.config().reward != general->config().reward) {
    throw InputError("the two networks aim at different reward presets (" + reward_preset_name(grid.config().reward) +
                     " for rectilinear faces, " + reward_preset_name(general->config().reward) + " for general ones)");
  }
  if (!general->deployed_region_policy("general")) {
    throw InputError("the network for general faces has no policy on them (a paper's agent trained before it learned on general faces)");
  }
  nlohmann::json meta = policy_meta(2, false, grid, grid_training);
  meta["general"] = {{"config", sac_config_json(general->config())}, {"training", general_training}};
  torch::serialize::OutputArchive archive;
  archive.write("meta", c10::IValue(meta.dump()));
  grid.save(archive, false);
  torch::serialize::OutputArchive nested;
  general->save(nested, false);
  archive.write("general", nested);
  write_archive(path, archive);
  return meta;
}

LoadedPolicy load_policy_file(const std::string& path, bool checkpoint) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": no such policy file");
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a policy file");
  torch::serialize::InputArchive archive;
  nlohmann::json meta;
  try {
    archive.load_from(path);
    c10::IValue text;
    archive.read("meta", text);
    meta = nlohmann::json::parse(text.toStringRef());
  } catch (const std::exception&) {
    throw InputError(path + ": not a readable AutoBlock policy file (corrupt or truncated)");
  }
  if (meta.value("format", "") != "autoblock-policy") throw InputError(path + ": not an AutoBlock policy file");
  const int version = meta.value("version", 0);
  if (version < 1 || version > kPolicyFormatVersion) {
    throw InputError(path + ": policy format version " + std::to_string(version) + " is not supported (this build reads " +
                     std::to_string(kPolicyFormatVersion) + ")");
  }
  if (checkpoint && meta.value("kind", "") != "checkpoint") {
    throw InputError(path + ": is a policy, not a training checkpoint (it cannot be resumed)");
  }
  if (version >= 2 && checkpoint) throw InputError(path + ": a policy with two networks is not a training checkpoint");
  LoadedPolicy loaded;
  loaded.meta = meta;
  try {
    loaded.agent = make_learning_agent(sac_config_from_json(meta.at("config")));
    loaded.agent->load(archive, checkpoint);
    if (meta.contains("general")) {
      loaded.general = make_learning_agent(sac_config_from_json(meta.at("general").at("config")));
      torch::serialize::InputArchive nested;
      archive.read("general", nested);
      loaded.general->load(nested, false);
    }
    if (checkpoint) {
      torch::Tensor blob;
      archive.read("replay_memory", blob);
      blob = blob.contiguous();
      const std::string bytes(reinterpret_cast<const char*>(blob.data_ptr<uint8_t>()), static_cast<size_t>(blob.numel()));
      loaded.agent->deserialize_memory(bytes);
    }
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  } catch (const std::exception&) {
    throw InputError(path + ": the policy file does not match its network configuration (corrupt or incompatible)");
  }
  return loaded;
}

nlohmann::json combine_policy_files(const std::string& grid_source, const std::string& general_source,
                                    const std::string& path) {
  const LoadedPolicy grid = load_policy_file(grid_source, false);
  const LoadedPolicy general = load_policy_file(general_source, false);
  const nlohmann::json general_training =
      general.general ? general.meta.at("general").value("training", nlohmann::json::object())
                      : general.meta.value("training", nlohmann::json::object());
  nlohmann::json grid_training = grid.meta.value("training", nlohmann::json::object());
  return save_two_agent_policy_file(path, *grid.agent, grid_training, general.general_agent(), general_training);
}

}  // namespace autoblock
