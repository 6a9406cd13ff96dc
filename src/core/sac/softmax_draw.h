// Drawing an index from softmax(q / temperature): the maximum-entropy policies' discrete choices in
// training (the paper agent's vertex, the lookahead agent's cut).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace autoblock {

// Inputs: q, not empty; temperature > 0; rng. Output: an index into q.
inline size_t sample_softmax(const std::vector<double>& q, double temperature, std::mt19937_64& rng) {
  const double top = *std::max_element(q.begin(), q.end());
  std::vector<double> weights;
  weights.reserve(q.size());
  for (const double v : q) weights.push_back(std::exp((v - top) / temperature));
  return static_cast<size_t>(std::discrete_distribution<int>(weights.begin(), weights.end())(rng));
}

}  // namespace autoblock
