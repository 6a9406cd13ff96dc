// The cut with the highest immediate reward (first in vertex order on ties).
#pragma once

#include "core/env/policy.h"

namespace autoblock {

class GreedyPolicy : public Policy {
 public:
  std::string name() const override { return "greedy"; }
  Action choose(const Episode& episode) override;
};

}  // namespace autoblock
