// One decomposition episode on a general face, as the grid engine's Episode (env/episode.h): cut
// the part at the front of a FIFO queue, set finished parts aside (blocks, block.h), queue the other
// pieces, and stop when no part is left (complete) or at the step cap (truncated).
//
// Actions: a cut (region_cut.h: full or partial, any angle, from any point of the part's boundary)
// or, on a convex part, finishing it with the template (block.h).
#pragma once

#include <array>
#include <deque>
#include <string>
#include <vector>

#include "core/env/episode.h"
#include "core/env/reward.h"
#include "core/region/block.h"
#include "core/region/region_cut.h"

namespace autoblock {

struct RegionAction {
  enum class Kind { Cut = 0, Template = 1 };
  Kind kind = Kind::Cut;
  RegionCut cut;  // for Kind::Cut
};

// "full", "partial" or "template".
std::string action_kind_name(const RegionAction& action);

struct RegionEpisodeOptions {
  int max_steps = 0;  // 0: automatic, 10 x (vertices of the face) + 10
  RewardPreset reward = RewardPreset::Paper;
  BlockRules rules;           // what a block is (block.h); see face_rules
  bool face_rules = true;     // the mesh preset: rules = mesh_block_rules(the face's loops) instead
  double corner_fraction = kMeshCornerFraction;  // face_rules: mesh_block_rules' fraction
  bool cut_smooth_parts = false;                 // face_rules: the rules' cut_smooth_parts (block.h)
};

struct RegionPiece {
  int id = 0;
  Region region;
};

// A finished part: a block with its four corners (indices into region.outer()), or a template.
struct FinishedRegion {
  int id = 0;
  Region region;
  bool is_template = false;
  std::array<int, 4> corners{};  // blocks only
};

struct RegionCutRecord {
  int part_id = 0;
  RegionAction action;
  int n_parts = 1;             // N: pieces the cut left (1: nothing changed; a template: 1)
  double reward = 0.0;
  std::vector<int> children;   // ids of the pieces ({part_id} when N = 1)
  std::vector<Chord> chords;   // the segments cut
};

class RegionEpisode {
 public:
  // Inputs: face, the whole face as a region (not empty); options.
  RegionEpisode(const Region& face, RegionEpisodeOptions options = {});

  const Region& face() const { return face_; }
  double face_size() const { return face_size_; }
  const RegionEpisodeOptions& options() const { return options_; }
  EpisodeStatus status() const { return status_; }
  bool running() const { return status_ == EpisodeStatus::Running; }
  int max_steps() const { return options_.max_steps; }
  int steps() const { return static_cast<int>(cuts_.size()); }

  // The part to cut next (front of the queue). Only while running.
  const Region& current_part() const { return queue_.front().region; }
  int current_part_id() const { return queue_.front().id; }

  // What an action on the current part would leave (a template: the part itself) and its reward,
  // without changing anything.
  CutOutcome outcome_of(const RegionAction& action) const;
  double reward_of(const RegionAction& action, const CutOutcome& outcome) const;

  // Applies the action to the current part. Throws std::logic_error when not running, or for a
  // template on a part it does not apply to.
  const RegionCutRecord& step(const RegionAction& action);
  // As step, with the outcome already computed by outcome_of(action).
  const RegionCutRecord& step(const RegionAction& action, CutOutcome outcome);

  // Raises the step cap by extra steps; a truncated episode with parts left runs again.
  void extend_steps(int extra);

  const std::vector<FinishedRegion>& finished() const { return finished_; }
  const std::deque<RegionPiece>& queue() const { return queue_; }
  const std::vector<RegionCutRecord>& cuts() const { return cuts_; }
  double total_return() const { return return_; }

 private:
  void push(Region region, std::vector<int>* ids);

  Region face_;
  double face_size_ = 1.0;
  RegionEpisodeOptions options_;
  EpisodeStatus status_ = EpisodeStatus::Running;
  std::deque<RegionPiece> queue_;
  std::vector<FinishedRegion> finished_;
  std::vector<RegionCutRecord> cuts_;
  double return_ = 0.0;
  int next_id_ = 0;
};

}  // namespace autoblock
