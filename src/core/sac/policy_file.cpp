#include "core/sac/policy_file.h"

#include <cstring>
#include <filesystem>

#include "core/common/error.h"
#include "core/io/atomic_file.h"
#include <torch/torch.h>

namespace autoblock {

namespace fs = std::filesystem;

void save_policy_file(const std::string& path, const LearningAgent& agent, const nlohmann::json& training,
                      bool checkpoint) {
  const nlohmann::json meta = {{"format", "autoblock-policy"},
                               {"version", kPolicyFormatVersion},
                               {"kind", checkpoint ? "checkpoint" : "policy"},
                               {"config", sac_config_json(agent.config())},
                               {"training", training}};
  torch::serialize::OutputArchive archive;
  archive.write("meta", c10::IValue(meta.dump()));
  agent.save(archive, checkpoint);
  if (checkpoint) {
    const std::string bytes = agent.serialize_memory();
    torch::Tensor blob = torch::empty({static_cast<int64_t>(bytes.size())}, torch::kUInt8);
    std::memcpy(blob.data_ptr<uint8_t>(), bytes.data(), bytes.size());
    archive.write("replay_memory", blob);
  }
  write_file_atomically(path, [&](const std::string& temporary) {
    try {
      archive.save_to(temporary);
      return true;
    } catch (const c10::Error&) {
      return false;
    }
  });
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
  LoadedPolicy loaded;
  loaded.meta = meta;
  try {
    loaded.agent = make_learning_agent(sac_config_from_json(meta.at("config")));
    loaded.agent->load(archive, checkpoint);
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

}  // namespace autoblock
