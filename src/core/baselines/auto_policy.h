// The default policy, "auto": the exact search where it finishes in time, a learned policy where it
// does not.
//
// For every part it runs the exact search (optimal_search.h, maximising the episode's reward preset) with a budget of part_seconds, while the search's total budget lasts. When the search
// finishes, its best line decides the cut ("optimal"). When it does not, the fallback policy (a
// learned policy, made on first need, so a face the search finishes never loads LibTorch) decides
// that one cut, and the search tries again on the smaller pieces. The exact values the search has
// finished stay memoised across parts. When the whole decomposition's time limit runs out, greedy
// finishes the remaining parts and time_capped() turns true. decided_by() names who chose each cut.
//
// Inputs: face_size (reward scale); options; make_fallback, a factory for the learned policy (it may
//         throw: auto then falls back to greedy and says so in decided_by).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/baselines/optimal_search.h"
#include "core/env/policy.h"

namespace autoblock {

struct AutoPolicyOptions {
  // The budgets (README, "The default policy"): on validation faces of up to 40 rectangles the
  // whole exact search took at most 0.8 s, and loading the learned runtime alone costs a process
  // about 0.8 s, so a face is searched for up to a second before a learned cut splits it.
  double part_seconds = 1.0;     // the exact search's budget per part
  double search_seconds = 2.0;   // the exact search's total budget per face
  double total_seconds = 30.0;   // the whole decomposition's time limit (<= 0: none)
};

class AutoPolicy : public Policy {
 public:
  AutoPolicy(double face_size, AutoPolicyOptions options, std::function<std::unique_ptr<Policy>()> make_fallback);
  std::string name() const override { return "auto"; }
  Action choose(const Episode& episode) override;
  bool time_capped() const override { return capped_; }
  std::string decided_by() const override { return decided_by_; }

 private:
  Action fallback(const Episode& episode);

  AutoPolicyOptions options_;
  double face_size_;
  std::optional<OptimalSearch> search_;  // made at the first choice, for the episode's reward preset
  std::function<std::unique_ptr<Policy>()> make_fallback_;
  std::unique_ptr<Policy> fallback_;
  bool fallback_failed_ = false;
  bool started_ = false;
  std::chrono::steady_clock::time_point start_;
  double searched_ = 0.0;  // the exact search's work so far, in seconds of it (kOptimalWorkPerSecond)
  bool capped_ = false;
  std::string decided_by_ = "auto";
};

// Inputs: policy; seconds, the time limit counted from its first choice (<= 0: none).
// Output: the policy, finished by greedy once the limit has passed (time_capped() then true).
std::unique_ptr<Policy> time_limited(std::unique_ptr<Policy> policy, double seconds);

}  // namespace autoblock
