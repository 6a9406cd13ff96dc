#include "core/sac/region_lookahead_policy.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/region/region_candidates.h"

namespace autoblock {

RegionLookaheadPolicy::RegionLookaheadPolicy(std::shared_ptr<LookaheadAgent> agent, std::string name)
    : agent_(std::move(agent)), name_(std::move(name)) {}

RegionStateOptions RegionLookaheadPolicy::state_options(const RegionEpisodeOptions& episode, double face_size) const {
  return agent_->region_state_options(face_size, episode.rules);
}

std::vector<double> RegionLookaheadPolicy::action_values(const RegionPartState& state, const RegionEpisodeOptions& episode,
                                                         double face_size) {
  std::vector<size_t> all(state.candidates.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = k;
  return values_of(state, all, episode, face_size);
}

std::vector<size_t> RegionLookaheadPolicy::shortlist(const RegionPartState& state) const {
  return best_candidates(state.candidates, static_cast<size_t>(std::max(0, agent_->config().deploy_top_k)));
}

std::vector<double> RegionLookaheadPolicy::values_of(const RegionPartState& state, const std::vector<size_t>& which,
                                                     const RegionEpisodeOptions& episode, double face_size) {
  // The pieces not valued yet, as one batch.
  std::vector<Region> fresh;
  std::vector<std::shared_ptr<const RegionPartState>> keep;
  std::vector<const PartState*> batch;
  for (const size_t k : which) {
    for (const Region& piece : state.candidates[k].to_cut) {
      if (values_.count(piece)) continue;
      values_.emplace(piece, 0.0);
      fresh.push_back(piece);
    }
  }
  if (!fresh.empty()) {
    for (const Region& piece : fresh) {
      keep.push_back(make_region_state(piece, state_options(episode, face_size)));
      batch.push_back(keep.back().get());
    }
    const std::vector<double> w = agent_->deployed_values(batch);
    for (size_t k = 0; k < fresh.size(); ++k) values_[fresh[k]] = w[k];
  }
  std::vector<double> q;
  q.reserve(which.size());
  for (const size_t k : which) {
    double value = state.candidates[k].reward;
    for (const Region& piece : state.candidates[k].to_cut) value += agent_->config().gamma * values_.at(piece);
    q.push_back(value);
  }
  return q;
}

RegionAction RegionLookaheadPolicy::choose(const RegionEpisode& episode) {
  if (episode.face().hash() != face_hash_ || episode.steps() == 0) {
    values_.clear();
    face_hash_ = episode.face().hash();
  }
  const Region& part = episode.current_part();
  const auto state = make_region_state(part, state_options(episode.options(), episode.face_size()));
  if (state->candidates.empty()) return progress_action(part, episode.options().rules);
  const std::vector<size_t> which = shortlist(*state);
  const std::vector<double> q = values_of(*state, which, episode.options(), episode.face_size());
  size_t best = 0;
  for (size_t k = 1; k < q.size(); ++k) {
    if (q[k] > q[best]) best = k;
  }
  return state->candidates[which[best]].action;
}

std::vector<float> RegionLookaheadPolicy::vertex_scores(const RegionEpisode& episode) {
  const Region& part = episode.current_part();
  std::vector<float> scores(static_cast<size_t>(part.vertex_count()), -std::numeric_limits<float>::infinity());
  const auto state = make_region_state(part, state_options(episode.options(), episode.face_size()));
  const std::vector<size_t> which = shortlist(*state);
  const std::vector<double> q = values_of(*state, which, episode.options(), episode.face_size());
  for (size_t k = 0; k < which.size(); ++k) {
    const int v = state->candidates[which[k]].vertex;
    if (v < 0 || static_cast<size_t>(v) >= scores.size()) continue;  // from an edge's midpoint, or a template
    float& score = scores[static_cast<size_t>(v)];
    score = std::max(score, static_cast<float>(q[k]));
  }
  return scores;
}

}  // namespace autoblock
