#include "core/api/face_actions.h"

#include "core/env/occt_replay.h"
#include "core/mesh/conformal_merge.h"

namespace autoblock {

InputFace check_face(const TopoDS_Face& face, const std::string& source) { return input_face_from_occt(face, source); }

FaceDecomposition decompose_input_face(const InputFace& face, const DecomposeSettings& settings) {
  check_reward_preset(settings.reward);
  const auto source = policy_source(settings.policy, settings.policy_settings);
  std::unique_ptr<Policy> policy = source->make(face.grid.size, settings.policy_settings.seed);
  EpisodeOptions options;
  options.max_steps = settings.max_steps;
  options.reward = settings.reward.empty() ? source->reward() : reward_preset_by_name(settings.reward);
  FaceDecomposition result;
  result.face = face;
  result.decomposition = decompose_face(face.grid, *policy, options);
  result.block_faces = replay_cuts_occt(face.occt, face.grid, result.decomposition.cuts, options);
  result.shape = conformal_merge(result.block_faces).compound;
  return result;
}

EpisodeSnapshot face_step(const InputFace& face, const std::vector<CutSpec>& cuts, int step, int max_steps,
                          RewardPreset reward) {
  EpisodeOptions options;
  options.max_steps = max_steps;
  options.reward = reward;
  return episode_snapshot(face.grid, cuts, step, options);
}

}  // namespace autoblock
