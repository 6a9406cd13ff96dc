// The paper's continuous agent (continuous_sac_agent.h) deployed on general faces.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/region/region_policy.h"
#include "core/sac/continuous_sac_agent.h"

namespace autoblock {

// The continuous agent deployed on general faces: the vertex (or the template) of highest value, the
// actor's mean angle. When that cut would not make progress (region_candidates.h), the next vertex by
// value; when none does, progress_action. The caller holds lock_general_engine().
// What its choices cost, counted (work(), in the search's units: kSearchWorkPerSecond): the part's
// vertex count for each cut tried, as the search counts a candidate, and kContinuousGraphEdgeWork per
// directed edge of the part's graph (its triangulation and the networks' passes over it): the
// lookahead policy's rate (kLookaheadGraphEdgeWork), not measured on this agent (no shipped policy).
constexpr long long kContinuousGraphEdgeWork = 42;

class ContinuousRegionPolicy : public RegionPolicy {
 public:
  ContinuousRegionPolicy(std::shared_ptr<ContinuousSacAgent> agent, SacConfig config, std::string name)
      : agent_(std::move(agent)), config_(std::move(config)), name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RegionAction choose(const RegionEpisode& episode) override;
  long long work() const override { return work_; }
  // The value of each vertex of the current part (the template's is not among them).
  std::vector<float> vertex_scores(const RegionEpisode& episode);

 private:
  std::shared_ptr<ContinuousSacAgent> agent_;
  SacConfig config_;
  std::string name_;
  FaceStart face_start_;
  long long work_ = 0;  // this face's
};

}  // namespace autoblock
