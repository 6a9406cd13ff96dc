#include "core/api/face_actions.h"

#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include "core/env/occt_replay.h"

namespace autoblock {

InputFace check_face(const TopoDS_Face& face, const std::string& source) { return input_face_from_occt(face, source); }

FaceDecomposition decompose_input_face(const InputFace& face, const DecomposeSettings& settings) {
  check_reward_preset(settings.reward);
  std::unique_ptr<Policy> policy = make_policy(settings.policy, face.grid, settings.policy_settings);
  EpisodeOptions options;
  options.max_steps = settings.max_steps;
  FaceDecomposition result;
  result.face = face;
  result.decomposition = decompose_face(face.grid, *policy, options);
  result.block_faces = replay_cuts_occt(face.occt, face.grid, result.decomposition.cuts, options);
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const TopoDS_Face& block : result.block_faces) builder.Add(compound, block);
  result.shape = compound;
  return result;
}

EpisodeSnapshot face_step(const InputFace& face, const std::vector<CutSpec>& cuts, int step, int max_steps) {
  EpisodeOptions options;
  options.max_steps = max_steps;
  return episode_snapshot(face.grid, cuts, step, options);
}

}  // namespace autoblock
