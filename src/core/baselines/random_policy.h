// The paper's comparison: cuts chosen uniformly at random.
#pragma once

#include <cstdint>
#include <random>

#include "core/env/policy.h"

namespace autoblock {

class RandomPolicy : public Policy {
 public:
  // Inputs: seed; splitting_only: draw only among the cuts that split the part (N >= 2), instead
  // of among all vertices and both directions.
  RandomPolicy(std::uint64_t seed, bool splitting_only);
  std::string name() const override { return splitting_only_ ? "random-split" : "random"; }
  Action choose(const Episode& episode) override;

 private:
  std::mt19937_64 rng_;
  bool splitting_only_;
};

}  // namespace autoblock
