// Run a policy over one face and collect everything a report needs.
#pragma once

#include <string>
#include <vector>

#include "core/env/episode.h"
#include "core/env/policy.h"

namespace autoblock {

struct Decomposition {
  std::string policy;
  RewardPreset reward = RewardPreset::Paper;  // the preset the cuts' rewards were computed with
  std::vector<Box> blocks;            // the rectangles, in model coordinates, in order set aside
  std::vector<CutRecord> cuts;
  std::vector<std::string> decided_by;  // per cut: which policy chose it (Policy::decided_by)
  std::vector<Part> unfinished;       // parts left when truncated
  double total_return = 0.0;          // plain sum of Eq. (1) over the cuts
  EpisodeStatus status = EpisodeStatus::Running;
  int min_blocks = 0;                 // minimum rectangles of any partition (a lower bound)
  double seconds = 0.0;               // wall time of the decomposition itself
  bool time_capped = false;           // the policy ran out of time and finished with a fallback (see Policy)
  bool complete() const { return status == EpisodeStatus::Complete; }
  bool truncated() const { return status == EpisodeStatus::Truncated; }
};

// Inputs:  face; policy; options (step cap).
// Outputs: the decomposition the policy makes of the face, with the wall time it took.
Decomposition decompose_face(const GridFace& face, Policy& policy, EpisodeOptions options = {});

}  // namespace autoblock
