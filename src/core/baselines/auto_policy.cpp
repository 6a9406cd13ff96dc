#include "core/baselines/auto_policy.h"

#include <algorithm>

#include "core/baselines/greedy_policy.h"

namespace autoblock {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A policy with a time limit; greedy once it has passed.
class TimeLimitedPolicy : public Policy {
 public:
  TimeLimitedPolicy(std::unique_ptr<Policy> inner, double seconds) : inner_(std::move(inner)), seconds_(seconds) {}
  std::string name() const override { return inner_->name(); }
  bool time_capped() const override { return capped_ || inner_->time_capped(); }
  std::string decided_by() const override { return capped_ ? "greedy" : inner_->decided_by(); }
  Action choose(const Episode& episode) override {
    if (!started_) {
      started_ = true;
      start_ = std::chrono::steady_clock::now();
    }
    if (!capped_ && seconds_since(start_) > seconds_) capped_ = true;
    if (capped_) return GreedyPolicy().choose(episode);
    return inner_->choose(episode);
  }

 private:
  std::unique_ptr<Policy> inner_;
  double seconds_;
  bool started_ = false, capped_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

AutoPolicy::AutoPolicy(double face_size, AutoPolicyOptions options, std::function<std::unique_ptr<Policy>()> make_fallback)
    : options_(options), face_size_(face_size), make_fallback_(std::move(make_fallback)) {}

Action AutoPolicy::fallback(const Episode& episode) {
  if (!fallback_ && !fallback_failed_) {
    try {
      fallback_ = make_fallback_();
    } catch (const std::exception&) {
      fallback_failed_ = true;  // no learned runtime: greedy stands in, and decided_by says so
    }
  }
  if (fallback_) {
    const Action action = fallback_->choose(episode);
    decided_by_ = fallback_->decided_by();
    return action;
  }
  decided_by_ = "greedy";
  return GreedyPolicy().choose(episode);
}

Action AutoPolicy::choose(const Episode& episode) {
  if (!started_) {
    started_ = true;
    start_ = std::chrono::steady_clock::now();
    search_.emplace(face_size_, 0.0, episode.reward_preset());
  }
  if (options_.total_seconds > 0 && seconds_since(start_) > options_.total_seconds) capped_ = true;
  if (capped_) {
    decided_by_ = "greedy";
    return GreedyPolicy().choose(episode);
  }
  // The search's budgets are counted in work (optimal_search.h), so that a face decomposes the same
  // on every machine; the whole decomposition's limit stays on the wall clock (it bounds the learned
  // fallback too).
  const double left = options_.search_seconds - searched_;
  if (left > 0) {
    search_->set_budget(std::max(std::min(options_.part_seconds, left), 1e-6));
    std::optional<AxisLine> line;
    try {
      line = search_->best_line(episode.current_part());
    } catch (const OptimalSearch::TimeLimit&) {
      // the fallback cuts this part
    }
    searched_ += static_cast<double>(search_->work()) / kOptimalWorkPerSecond;
    if (line) {
      decided_by_ = "optimal";
      return action_on_line(episode, *line);
    }
  }
  return fallback(episode);
}

std::unique_ptr<Policy> time_limited(std::unique_ptr<Policy> policy, double seconds) {
  if (seconds <= 0) return policy;
  return std::make_unique<TimeLimitedPolicy>(std::move(policy), seconds);
}

}  // namespace autoblock
