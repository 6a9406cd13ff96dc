// A decomposition policy: given a running episode, pick the next action on its current part.
#pragma once

#include <string>

#include "core/env/episode.h"

namespace autoblock {

class Policy {
 public:
  virtual ~Policy() = default;
  // The policy's name in reports ("greedy", a policy file's path, ...).
  virtual std::string name() const = 0;
  // Inputs: episode, running. Output: an action on episode.current_part().
  virtual Action choose(const Episode& episode) = 0;
  // True when a policy ran out of its time budget and finished with a fallback.
  virtual bool time_capped() const { return false; }
  // Which policy decided the action choose() returned last (a composite policy names its member:
  // "optimal", "sac-mesh", "greedy", ...).
  virtual std::string decided_by() const { return name(); }
};

}  // namespace autoblock
