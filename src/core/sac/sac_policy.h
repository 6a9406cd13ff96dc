// A trained agent as a deployed decomposition policy.
//
// As the paper deploys it: the model vertex where the value network is highest, and the direction
// the actor prefers there. One addition: a cut that cannot change the part (N = 1) is never
// chosen, so a deterministic policy can never repeat a useless cut forever: when the preferred
// cut at the best vertex runs only along the boundary, the next-best vertex is tried (and, if no
// vertex's preferred direction splits the part, the best vertex that splits it either way).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/env/policy.h"
#include "core/sac/sac_agent.h"

namespace autoblock {

class SacPolicy : public Policy {
 public:
  // Inputs: agent, shared (it is not changed); name, for reports.
  SacPolicy(std::shared_ptr<SacAgent> agent, std::string name);
  std::string name() const override { return name_; }
  Action choose(const Episode& episode) override;

  // The value network's score at every model vertex of the episode's current part
  // (Episode::current_vertices order), e.g. for pictures.
  std::vector<float> vertex_scores(const Episode& episode);

 private:
  std::shared_ptr<SacAgent> agent_;
  std::string name_;
};

}  // namespace autoblock
