// The lookahead agent deployed on general faces (issue 12): a RegionPolicy that values every
// candidate action of the current part (region_lookahead.h) as
//   Q(P, a) = reward(P, a) + gamma * sum over the pieces a leaves that are not blocks of W(piece),
// W the agent's deployed value network on the pieces' states (region_state.h), rewards and features
// under the agent's reward preset (what W learned; the episode's rules), and takes the best
// (the earlier candidate among equals). A piece's state holds its own lookahead (every candidate of
// it cut), so valuing every candidate's pieces costs about the square of the candidates' count: with
// the agent's deploy_top_k = k > 0 only the k best candidates by reward are valued, with the O-grid
// and a reflex fillet's corner template always among them (shortlist, best_candidates in
// region_lookahead.h). The template and an O-grid finish the part: their Q is their
// reward. A part with no candidate that makes progress gets progress_action, so every face ends in
// blocks. Within a decomposition a piece's value is computed once (kept by the part, which is a
// canonical value). With the agent's actor_candidates > 0, the actor's proposals (cut_proposer.h, at
// its mean angle) join the shortlist as candidates valued the same way. What lookahead_agent.h says of the grid holds (gamma, the reward scale inside
// W); the agent learns on grid and general faces alike (lookahead_agent.h, issue 12).
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/region/region_policy.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/region_state.h"

namespace autoblock {

// What its choices cost, counted (work(), in the search's units, so that TimedRegionPolicy's budget is
// the search's: kSearchWorkPerSecond): the candidates measured on the part and on each piece valued, as
// the search counts them (SearchWork), and kLookaheadGraphEdgeWork per directed edge of each state's
// graph made (its triangulation, the value network's and the actor's passes over it). Measured with
// sac-mesh on this machine (BENCHMARKS.md, "`auto`'s and `optimal`'s search budgets in work"): 42 units
// an edge is the median over 34 general faces whose decomposition took over 0.05 s; counted against
// wall time, polygons of 13-40 vertices 1.00, faces with arcs 1.06, plates with holes 0.82 (medians).
constexpr long long kLookaheadGraphEdgeWork = 42;

class RegionLookaheadPolicy : public RegionPolicy {
 public:
  RegionLookaheadPolicy(std::shared_ptr<LookaheadAgent> agent, std::string name);
  std::string name() const override { return name_; }
  RegionAction choose(const RegionEpisode& episode) override;
  long long work() const override { return work_.spent; }
  // Inputs: state, a part's (state_options: with lookahead); the episode's options; face_size.
  // Output: Q of each of state.candidates.
  std::vector<double> action_values(const RegionPartState& state, const RegionEpisodeOptions& episode, double face_size);
  // Inputs: state, a part's. Output: the candidates whose pieces are valued when deployed, in their
  //         order: the agent's deploy_top_k best by reward (the earlier among equals) and the
  //         candidates marked always, or all (0).
  std::vector<size_t> shortlist(const RegionPartState& state) const;
  // Inputs: the episode's options; face_size. Output: the options of the states this policy reads:
  //         lookahead with the episode's rules and the agent's reward preset (what W learned).
  RegionStateOptions state_options(const RegionEpisodeOptions& episode, double face_size) const;
  // Inputs: episode, running. Output: at every vertex of its current part (loops flattened, outer
  //         first: RegionSnapshot::vertices' order) the best Q among the shortlisted candidates that
  //         start at it (what the step-through panel shows); -infinity at a vertex none starts at.
  std::vector<float> vertex_scores(const RegionEpisode& episode);

 private:
  std::vector<double> values_of(const std::vector<const RegionCandidate*>& candidates, const RegionEpisodeOptions& episode,
                                double face_size);
  // The shortlist of the part's state and the actor's proposals that make progress, as candidates.
  std::vector<const RegionCandidate*> contenders(const Region& part, const RegionPartState& state,
                                                 const RegionEpisodeOptions& episode, double face_size,
                                                 std::vector<RegionCandidate>& proposed);
  std::shared_ptr<LookaheadAgent> agent_;
  std::string name_;
  FaceStart face_start_;
  std::unordered_map<Region, double, RegionHash> values_;  // W of the pieces valued in this face
  SearchWork work_;  // this face's, counted, never stopped (above)
};

}  // namespace autoblock
