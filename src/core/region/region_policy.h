// Policies of the general engine, and the run of one over a face.
//
//   greedy  the candidate (region_candidates.h) that makes progress with the highest immediate
//           reward; ties go to the first listed;
//   random  uniform over the candidates that make progress (and the template);
//   search  a lookahead over the candidates with memoisation on parts (region_search.h).
// decompose_region runs a policy up to the step cap and then finishes every part left with
// progress_action (region_candidates.h), which always terminates: every face ends in blocks
// (or templates), whatever the policy.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include "core/region/region_episode.h"

namespace autoblock {

class RegionPolicy {
 public:
  virtual ~RegionPolicy() = default;
  virtual std::string name() const = 0;
  // Inputs: episode, running. Output: an action on episode.current_part().
  virtual RegionAction choose(const RegionEpisode& episode) = 0;
  // True when the policy ran out of its time budget and finished with a fallback.
  virtual bool time_capped() const { return false; }
  // The work its scoring did on the face so far (SearchWork units; 0 for a policy that counts none).
  virtual long long work() const { return 0; }
};

// What a policy keeps per face (a memo, a budget, its work) starts again at a new face: another face
// than the last choice's, or an episode at its first step.
class FaceStart {
 public:
  // Inputs: episode, about to be chosen for. Output: true when it begins a new face (then remembered).
  bool operator()(const RegionEpisode& episode) {
    if (started_ && episode.face().hash() == hash_ && episode.steps() > 0) return false;
    started_ = true;
    hash_ = episode.face().hash();
    return true;
  }

 private:
  bool started_ = false;
  size_t hash_ = 0;
};

class RegionGreedyPolicy : public RegionPolicy {
 public:
  std::string name() const override { return "greedy"; }
  RegionAction choose(const RegionEpisode& episode) override;
};

class RegionRandomPolicy : public RegionPolicy {
 public:
  explicit RegionRandomPolicy(std::uint64_t seed) : rng_(seed) {}
  std::string name() const override { return "random"; }
  RegionAction choose(const RegionEpisode& episode) override;

 private:
  std::mt19937_64 rng_;
};

// A policy with a time budget per face (a learned policy on general faces: what the grid's learned
// policies do under --time-limit): the wrapped policy makes a face's first choice, and chooses on
// until its work on the face (work(), in the search's units) passes `seconds` x kSearchWorkPerSecond
// (region_search.h); then greedy finishes the parts left and time_capped() says so. Counted, not
// timed, so that a face decomposes the same on every machine; the wall clock backs it
// (search_wall_backstop). A new face (FaceStart) starts the count again.
// Inputs: policy, not null; seconds (<= 0: no limit, the policy alone).
class TimedRegionPolicy : public RegionPolicy {
 public:
  TimedRegionPolicy(std::unique_ptr<RegionPolicy> policy, double seconds);
  std::string name() const override { return policy_->name(); }
  RegionAction choose(const RegionEpisode& episode) override;
  bool time_capped() const override { return capped_ || policy_->time_capped(); }
  long long work() const override { return policy_->work(); }
  RegionPolicy& inner() { return *policy_; }

 private:
  std::unique_ptr<RegionPolicy> policy_;
  double seconds_;
  RegionGreedyPolicy greedy_;
  FaceStart face_start_;
  bool capped_ = false;
  std::chrono::steady_clock::time_point deadline_;  // the wall-clock backstop
};

// The best candidate by immediate reward, with its outcome (shared by greedy and search).
struct ScoredAction {
  RegionAction action;
  std::shared_ptr<const CutOutcome> outcome;  // shared by candidates with the same outcome
  double reward = 0.0;
};

// The work of scoring candidates, counted so that a budget of it decides the same on every machine
// and under any load (a wall clock does not: a plate of scores of holes, whose searches run out of
// budget, meshed up to 0.15 apart between two runs): each candidate measured on a part charges the
// part's vertex count, what cutting it costs.
struct SearchWork {
  long long spent = 0;
  long long stop = 0;  // scoring stops once spent passes it (at least one candidate scored); 0: never
  bool past() const { return stop > 0 && spent > stop; }
};

// Inputs:  part; face_size; reward preset and rules (as the episode's); work (optional: charged, and
//          its stop obeyed); keep,
//          how many of the best candidates the caller needs (0: all).
// Outputs: the candidates of region_candidates(part) that make progress, with their outcomes and
//          rewards, in order: every one when keep is 0; else at least every one that could be among
//          the keep best by reward (the first of equals first), the others left out when a bound of
//          their reward (region_cut_reward_bound) shows they cannot be. Past work's stop, only those
//          scored so far (at least one, if any). taper: each cut's reward less the taper charge of
//          the blocks it leaves (pieces_taper_cost, region_reward.h; the search's ranking).
std::vector<ScoredAction> score_candidates(const Region& part, double face_size, const RegionEpisodeOptions& options,
                                          SearchWork* work = nullptr, size_t keep = 0, bool taper = false);

struct RegionDecomposition {
  std::string policy;
  RewardPreset reward = RewardPreset::Paper;
  BlockRules rules;                      // what a block was (the episode's, block.h)
  std::vector<FinishedRegion> finished;  // blocks and templates, in the order set aside
  std::vector<RegionCutRecord> cuts;
  std::vector<Region> unfinished;        // parts left when not complete
  double total_return = 0.0;
  EpisodeStatus status = EpisodeStatus::Running;
  int policy_steps = 0;         // actions the policy chose; the rest came from progress_action
  int blocks = 0, templates = 0;
  double seconds = 0.0;
  bool time_capped = false;
  long long work = 0;           // the policy's scoring work (RegionPolicy::work)
  // Kept by mesh_input_face's tries (api/face_meshing.h) for its mesh: at least this many intervals per
  // model edge (MeshOptions::min_edge_intervals) meshes it as well as it was judged. 1 otherwise.
  int min_edge_intervals = 1;
  // Set by mesh_input_face when the policy asked for (not the search) gave blocks that do not mesh:
  // that policy and why; these are the search's blocks (empty: no fallback).
  std::string fallback_from, fallback_reason;
  bool complete() const { return status == EpisodeStatus::Complete; }
};

// One general computation at a time: region/ builds CGAL without thread support (see
// src/core/CMakeLists.txt), and front ends may call the general engine from several threads (eval's
// workers). Whoever runs a decomposition, a replay or a step on regions holds this lock.
std::unique_lock<std::mutex> lock_general_engine();

// Inputs:  episode (ended or not); policy, the name to record. Outputs: its decomposition (finished
//          parts, cuts, return, status, the parts left, the rules it ran with); the caller fills
//          policy_steps, time_capped and seconds.
RegionDecomposition episode_decomposition(const RegionEpisode& episode, const std::string& policy);

// Inputs:  face (a region, not empty); policy; options.
// Outputs: the decomposition, complete unless an action failed to make progress on some part.
RegionDecomposition decompose_region(const Region& face, RegionPolicy& policy, RegionEpisodeOptions options = {});

}  // namespace autoblock
