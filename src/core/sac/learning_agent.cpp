#include "core/sac/learning_agent.h"

#include "core/common/error.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/paper_agent.h"

namespace autoblock {

std::shared_ptr<LearningAgent> make_learning_agent(const SacConfig& config) {
  if (config.agent == "paper") return std::make_shared<PaperAgent>(config);
  if (config.agent == "lookahead") return std::make_shared<LookaheadAgent>(config);
  throw InputError("unknown agent '" + config.agent + "' (expected paper or lookahead)");
}

}  // namespace autoblock
