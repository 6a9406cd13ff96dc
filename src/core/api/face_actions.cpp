#include "core/api/face_actions.h"

#include <stdexcept>

#include "core/common/error.h"
#include "core/env/occt_replay.h"
#include "core/mesh/conformal_merge.h"

namespace autoblock {

InputFace check_face(const TopoDS_Face& face, const std::string& source) { return input_face_from_occt(face, source); }

std::vector<FaceSummary> shape_faces(const TopoDS_Shape& shape) { return list_faces(shape); }

InputFace check_shape_face(const TopoDS_Shape& shape, const std::string& source, int face_number,
                           const std::string& how_to_choose) {
  return input_face_from_occt(select_face(shape, source, face_number, how_to_choose),
                              face_source_name(source, face_number));
}

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

std::vector<double> face_vertex_scores(const InputFace& face, const std::vector<CutSpec>& cuts, int step,
                                       const std::string& policy, int max_steps, RewardPreset reward) {
  const auto source = policy_source(policy, PolicySettings{});
  const std::shared_ptr<LearnedPolicy> scorer = source->scoring_policy();
  if (!scorer) {
    throw InputError("the policy '" + source->name() +
                     "' is a baseline: it has no value network, so there are no vertex scores");
  }
  EpisodeOptions options;
  options.max_steps = max_steps;
  options.reward = reward;
  const Episode episode = replay_episode(face.grid, cuts, step, options);
  if (!episode.running()) {
    throw InputError("no cut follows step " + std::to_string(step) + ": the episode is over, there is no part to score");
  }
  const std::vector<float> scores = scorer->vertex_scores(episode);
  return std::vector<double>(scores.begin(), scores.end());
}

FaceMesh face_mesh(const InputFace& face, const std::vector<CutSpec>& cuts, int max_steps, RewardPreset reward,
                   MeshOptions options) {
  options.episode.max_steps = max_steps;
  options.episode.reward = reward;
  FaceMesh out;
  out.decomposition = replay_decomposition(face.grid, cuts, options.episode, "replay");
  out.result = mesh_decomposition(face, out.decomposition, options);
  if (!out.result.conformity.conformal) {
    throw std::runtime_error("the mesh failed the conformity check: " + out.result.conformity.problem);
  }
  return out;
}

}  // namespace autoblock
