// The squashed Gaussian action of SAC's continuous actors: an actor row (mu, raw log std), a draw
// z = mu + sigma eps and the action u = tanh(z) in [-1, 1], with its log density
//   log pi(u) = log N(eps) - log sigma - log(1 - u^2)   (SAC's tanh correction).
// Shared by the paper's agent's angle (continuous_sac_agent.h) and the lookahead agent's
// proposal actor (cut_proposer.h).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <torch/torch.h>

namespace autoblock {

constexpr double kLogStdMin = -5.0, kLogStdMax = 2.0;  // the actor's log std, clamped
constexpr double kSquashEpsilon = 1e-6;                 // keeps log(1 - u^2) finite at |u| = 1

// Inputs: out, the actor's output [B, 2]. Output: its clamped log std per row [B].
inline torch::Tensor clamped_log_std(const torch::Tensor& out) { return out.select(1, 1).clamp(kLogStdMin, kLogStdMax); }

// Inputs: eps, the standard normal draws [B]; log_std, clamped [B]; u, the actions [B].
// Output: log pi(u) per row [B] (above).
inline torch::Tensor squashed_log_density(const torch::Tensor& eps, const torch::Tensor& log_std, const torch::Tensor& u) {
  return -0.5 * eps.pow(2) - log_std - 0.5 * std::log(2.0 * M_PI) - torch::log(1.0 - u.pow(2) + kSquashEpsilon);
}

// Inputs: rows, each N numbers. Output: a (count x N) float tensor of them.
template <size_t N>
torch::Tensor stack_rows(const std::vector<const std::array<float, N>*>& rows) {
  torch::Tensor t = torch::empty({static_cast<int64_t>(rows.size()), static_cast<int64_t>(N)}, torch::kFloat32);
  float* data = t.data_ptr<float>();
  for (size_t b = 0; b < rows.size(); ++b) {
    for (size_t k = 0; k < N; ++k) data[b * N + k] = (*rows[b])[k];
  }
  return t;
}

}  // namespace autoblock
