#include "core/sac/learning_agent.h"

#include "core/common/error.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/paper_agent.h"
#include "core/region/region_policy.h"

namespace autoblock {

EpisodeRecord LearningAgent::train_region_episode(const Region&, std::mt19937_64&, int) {
  throw InputError("the " + config().agent + " agent learns on faces whose edges run along two perpendicular directions "
                   "only; train the lookahead agent on faces with edges at other angles");
}

std::unique_ptr<RegionPolicy> LearningAgent::deployed_region_policy(const std::string&) { return nullptr; }

std::vector<float> LearningAgent::region_vertex_scores(const RegionEpisode&) {
  throw InputError("the paper's agent has no value scores on faces with edges at other angles: its policy works on "
                   "rectilinear faces only");
}

std::shared_ptr<LearningAgent> make_learning_agent(const SacConfig& config) {
  if (config.agent == "paper") return std::make_shared<PaperAgent>(config);
  if (config.agent == "lookahead") return std::make_shared<LookaheadAgent>(config);
  throw InputError("unknown agent '" + config.agent + "' (expected paper or lookahead)");
}

}  // namespace autoblock
