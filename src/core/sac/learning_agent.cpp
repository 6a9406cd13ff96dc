#include "core/sac/learning_agent.h"

#include <sstream>

#include <torch/serialize.h>

#include "core/common/error.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/paper_agent.h"
#include "core/region/region_policy.h"

namespace autoblock {

EpisodeRecord LearningAgent::train_region_episode(const Region&, std::mt19937_64&, int) {
  throw InputError("this " + config().agent + " agent learns on faces whose edges run along two perpendicular directions "
                   "only (written before the paper's agent learned on general faces); start a fresh run for faces with "
                   "edges at other angles");
}

std::unique_ptr<RegionPolicy> LearningAgent::deployed_region_policy(const std::string&) { return nullptr; }

std::vector<float> LearningAgent::region_vertex_scores(const RegionEpisode&) {
  throw InputError("this policy has no value scores on faces with edges at other angles: it was trained before the "
                   "paper's agent learned on general faces");
}

void LearningAgent::copy_weights_from(const LearningAgent& other) {
  if (other.config().agent != config().agent) {
    throw InputError("the initial policy is the " + other.config().agent + " agent's and the run trains the " +
                     config().agent + " agent");
  }
  if (other.config().value_network != config().value_network) {
    throw InputError("the initial policy's value network is '" + other.config().value_network + "' and the run's is '" +
                     config().value_network + "'");
  }
  std::stringstream bytes;
  {
    torch::serialize::OutputArchive out;
    other.save(out, false);
    out.save_to(bytes);
  }
  torch::serialize::InputArchive in;
  try {
    in.load_from(bytes);
    load(in, false);
  } catch (const c10::Error& e) {
    throw InputError("the initial policy's networks do not fit the run's configuration");
  }
}

std::shared_ptr<LearningAgent> make_learning_agent(const SacConfig& config) {
  if (config.agent == "paper") return std::make_shared<PaperAgent>(config);
  if (config.agent == "lookahead") return std::make_shared<LookaheadAgent>(config);
  throw InputError("unknown agent '" + config.agent + "' (expected paper or lookahead)");
}

}  // namespace autoblock
