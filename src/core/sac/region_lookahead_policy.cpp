#include "core/sac/region_lookahead_policy.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/region/region_candidates.h"
#include "core/sac/deploy_profile.h"

namespace autoblock {

RegionLookaheadPolicy::RegionLookaheadPolicy(std::shared_ptr<LookaheadAgent> agent, std::string name)
    : agent_(std::move(agent)), name_(std::move(name)) {}

RegionStateOptions RegionLookaheadPolicy::state_options(const RegionEpisodeOptions& episode, double face_size) const {
  return agent_->region_state_options(face_size, episode.rules);
}

std::vector<double> RegionLookaheadPolicy::action_values(const RegionPartState& state, const RegionEpisodeOptions& episode,
                                                         double face_size) {
  std::vector<const RegionCandidate*> all;
  for (const RegionCandidate& c : state.candidates) all.push_back(&c);
  return values_of(all, episode, face_size);
}

std::vector<size_t> RegionLookaheadPolicy::shortlist(const RegionPartState& state) const {
  return best_candidates(state.candidates, static_cast<size_t>(std::max(0, agent_->config().deploy_top_k)));
}

std::vector<double> RegionLookaheadPolicy::values_of(const std::vector<const RegionCandidate*>& candidates,
                                                     const RegionEpisodeOptions& episode, double face_size) {
  // The pieces not valued yet, as one batch.
  std::vector<Region> fresh;
  std::vector<std::shared_ptr<const RegionPartState>> keep;
  std::vector<const PartState*> batch;
  for (const RegionCandidate* candidate : candidates) {
    for (const Region& piece : candidate->to_cut) {
      if (values_.count(piece)) continue;
      values_.emplace(piece, 0.0);
      fresh.push_back(piece);
    }
  }
  if (!fresh.empty()) {
    RegionStateOptions options = state_options(episode, face_size);
    options.work = &work_;
    for (const Region& piece : fresh) {
      keep.push_back(make_region_state(piece, options));
      work_.spent += kLookaheadGraphEdgeWork * keep.back()->graph.edge_count();
      batch.push_back(keep.back().get());
    }
    const std::vector<double> w = agent_->deployed_values(batch);
    for (size_t k = 0; k < fresh.size(); ++k) values_[fresh[k]] = w[k];
  }
  std::vector<double> q;
  q.reserve(candidates.size());
  for (const RegionCandidate* candidate : candidates) {
    double value = candidate->reward;
    for (const Region& piece : candidate->to_cut) value += agent_->config().gamma * values_.at(piece);
    q.push_back(value);
  }
  return q;
}

std::vector<const RegionCandidate*> RegionLookaheadPolicy::contenders(const Region& part, const RegionPartState& state,
                                                                      const RegionEpisodeOptions& episode, double face_size,
                                                                      std::vector<RegionCandidate>& proposed) {
  std::vector<const RegionCandidate*> result;
  for (const size_t k : shortlist(state)) result.push_back(&state.candidates[k]);
  proposed.clear();
  for (auto& proposal : agent_->propose_cuts(part, state, face_size, episode.rules, nullptr)) {
    ++deploy_profile().proposals;
    work_.spent += part.vertex_count();  // its cut measured, as a candidate is
    if (proposal.candidate) proposed.push_back(std::move(*proposal.candidate));
  }
  deploy_profile().proposals_progress += static_cast<long>(proposed.size());
  for (const RegionCandidate& c : proposed) result.push_back(&c);
  return result;
}

RegionAction RegionLookaheadPolicy::choose(const RegionEpisode& episode) {
  if (face_start_(episode)) {
    values_.clear();
    work_ = SearchWork{};
  }
  const Region& part = episode.current_part();
  RegionStateOptions options = state_options(episode.options(), episode.face_size());
  options.work = &work_;
  const auto state = make_region_state(part, options);
  work_.spent += kLookaheadGraphEdgeWork * state->graph.edge_count();
  if (state->candidates.empty()) return progress_action(part, episode.options().rules);
  std::vector<RegionCandidate> proposed;
  const std::vector<const RegionCandidate*> which = contenders(part, *state, episode.options(), episode.face_size(), proposed);
  const std::vector<double> q = values_of(which, episode.options(), episode.face_size());
  size_t best = 0;
  for (size_t k = 1; k < q.size(); ++k) {
    if (q[k] > q[best]) best = k;
  }
  if (best + proposed.size() >= which.size()) ++deploy_profile().proposals_chosen;
  return which[best]->action;
}

std::vector<float> RegionLookaheadPolicy::vertex_scores(const RegionEpisode& episode) {
  const Region& part = episode.current_part();
  std::vector<float> scores(static_cast<size_t>(part.vertex_count()), -std::numeric_limits<float>::infinity());
  const auto state = make_region_state(part, state_options(episode.options(), episode.face_size()));
  std::vector<RegionCandidate> proposed;
  const std::vector<const RegionCandidate*> which = contenders(part, *state, episode.options(), episode.face_size(), proposed);
  const std::vector<double> q = values_of(which, episode.options(), episode.face_size());
  for (size_t k = 0; k < which.size(); ++k) {
    const int v = which[k]->vertex;
    if (v < 0 || static_cast<size_t>(v) >= scores.size()) continue;  // from an edge's midpoint, or a template
    float& score = scores[static_cast<size_t>(v)];
    score = std::max(score, static_cast<float>(q[k]));
  }
  return scores;
}

}  // namespace autoblock
