// The actions front ends run on one face, one call each: check it, decompose it, show a step of
// its decomposition. The CLI and the Python binding (and so the FreeCAD workbench) call these and
// only convert their inputs and outputs.
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "core/api/catalog.h"
#include "core/env/decomposition.h"
#include "core/env/episode_snapshot.h"
#include "core/io/input_face.h"

namespace autoblock {

struct DecomposeSettings {
  std::string policy;                           // a name of policy_names() or a policy file; empty: the default
  std::string reward = default_reward_preset();  // empty: the policy's own preset
  PolicySettings policy_settings;
  int max_steps = 0;                           // 0: automatic (see EpisodeOptions)
};

struct FaceDecomposition {
  InputFace face;
  Decomposition decomposition;
  std::vector<TopoDS_Face> block_faces;  // cut from the input face by OpenCASCADE, in the order set
                                         // aside; then the unfinished parts if truncated
  TopoDS_Shape shape;                    // the partitioned face: the blocks merged conformally
                                         // (neighbours share edges and vertices, see conformal_merge.h)
};

// Inputs:  face, any OpenCASCADE face; source, its name for messages.
// Outputs: the face in every form (validated). Throws InputError saying what is wrong and where.
InputFace check_face(const TopoDS_Face& face, const std::string& source);

// Inputs:  face, a checked face; settings.
// Outputs: the decomposition and its blocks as faces. Throws InputError for a bad policy or reward
//          preset; std::logic_error / std::runtime_error when OpenCASCADE fails or disagrees.
FaceDecomposition decompose_input_face(const InputFace& face, const DecomposeSettings& settings);

// Inputs:  face, a checked face; cuts, its decomposition's cut sequence by position; step;
//          max_steps and reward, as the sequence was made (Decomposition::reward).
// Outputs: the episode at that step (see episode_snapshot.h). Throws InputError when the step is
//          out of range or the cuts do not belong to the face.
EpisodeSnapshot face_step(const InputFace& face, const std::vector<CutSpec>& cuts, int step, int max_steps = 0,
                          RewardPreset reward = RewardPreset::Paper);

}  // namespace autoblock
