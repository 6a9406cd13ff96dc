// The actions front ends run on one face, one call each: check it, decompose it, show a step of
// its decomposition. The CLI and the Python binding (and so the FreeCAD workbench) call these and
// only convert their inputs and outputs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "core/api/catalog.h"
#include "core/env/decomposition.h"
#include "core/env/episode_snapshot.h"
#include "core/io/face_selection.h"
#include "core/io/input_face.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/region/region_policy.h"
#include "core/region/region_snapshot.h"

namespace autoblock {

struct DecomposeSettings {
  std::string policy;                           // a name of policy_names() or a policy file; empty: the default
  std::string reward = default_reward_preset();  // empty: the policy's own preset
  PolicySettings policy_settings;
  int max_steps = 0;                           // 0: automatic (see EpisodeOptions)
  bool occt_blocks = true;                     // cut the blocks from the face with OpenCASCADE and merge them
  double corner_fraction = kMeshCornerFraction;  // general faces, mesh preset: a block's corners within
                                                 // [asin(f B), 180 - asin(f B)] degrees (block.h)
  bool cut_smooth_parts = false;                 // general faces, mesh preset: BlockRules::cut_smooth_parts
  // A general face searched (auto, search): the decomposition `autoblock mesh` keeps, by the tries of
  // mesh_input_face (api/face_meshing.h), each meshed at the default size: the one whose mesh is best
  // (its block rules, RegionDecomposition::rules, and min_edge_intervals say how to replay and mesh it).
  // Another policy on a general face: its decomposition, meshed once; when its blocks do not mesh, the
  // search's tries (RegionDecomposition::fallback_from says so). false: one decomposition by the
  // policy with the settings as they are (what eval measures).
  bool mesh_tries = true;
};

struct FaceDecomposition {
  InputFace face;
  Decomposition decomposition;           // a rectilinear face's, by the grid engine (in the face's frame)
  RegionDecomposition region;            // a general face's (face.is_general()), by the general engine
  std::vector<TopoDS_Face> block_faces;  // cut from the input face by OpenCASCADE, in the order set
                                         // aside; then the unfinished parts if truncated. In the
                                         // model's coordinates. Empty unless settings.occt_blocks.
  TopoDS_Shape shape;                    // the partitioned face: the blocks merged conformally
                                         // (neighbours share edges and vertices, see conformal_merge.h)
  bool general() const { return face.is_general(); }
};

// Inputs:  face, any OpenCASCADE face; source, its name for messages.
// Outputs: the face in every form (validated). Throws InputError saying what is wrong and where.
InputFace check_face(const TopoDS_Face& face, const std::string& source);

// Inputs:  shape, e.g. a part read from a file.
// Outputs: its faces, numbered as FreeCAD numbers them (Face1, Face2, ...), with surface, area, normal
//          and whether AutoBlock takes each (see face_selection.h).
std::vector<FaceSummary> shape_faces(const TopoDS_Shape& shape);

// Inputs:  shape; source, its name for messages; face_number, 1-based (0: the shape's only face);
//          how_to_choose, said when the choice is missing or out of range.
// Outputs: that face, checked. Throws InputError naming what the shape holds, or what is wrong with
//          the face and where.
InputFace check_shape_face(const TopoDS_Shape& shape, const std::string& source, int face_number,
                           const std::string& how_to_choose = "");

// Inputs:  face, a checked face; settings.
// Outputs: the decomposition and its blocks as faces: a rectilinear face by the grid engine with any
//          policy of policy_names() or a policy file, a general face by the general engine with a
//          policy of general_policy_names() or a lookahead agent's trained policy (a shipped name or a
//          file: sac/region_lookahead_policy.h). Throws InputError for a bad policy or reward preset
//          (or the paper's agent on a general face); std::logic_error / std::runtime_error when
//          OpenCASCADE fails or disagrees.
FaceDecomposition decompose_input_face(const InputFace& face, const DecomposeSettings& settings);

// Inputs:  face, a checked face; cuts, its decomposition's cut sequence by position; step;
//          max_steps and reward, as the sequence was made (Decomposition::reward).
// Outputs: the episode at that step (see episode_snapshot.h). Throws InputError when the step is
//          out of range or the cuts do not belong to the face.
EpisodeSnapshot face_step(const InputFace& face, const std::vector<CutSpec>& cuts, int step, int max_steps = 0,
                          RewardPreset reward = RewardPreset::Paper);

// face_step for a general face (face.is_general()): actions, its decomposition's sequence by position
// (region_action_specs of FaceDecomposition::region.cuts, in the face's frame); reward, the preset it
// was scored with (RegionDecomposition::reward); rules, the block rules it was made with
// (RegionDecomposition::rules; none: the face's own for the mesh preset, as a search makes them).
// Outputs: the episode at that step (see region_snapshot.h). Throws InputError when the face is
//          rectilinear (its cuts are CutSpecs), the step is out of range or an action does not belong
//          to the face.
RegionSnapshot face_step_general(const InputFace& face, const std::vector<RegionActionSpec>& actions, int step,
                                 int max_steps = 0, RewardPreset reward = RewardPreset::Paper,
                                 const std::optional<BlockRules>& rules = std::nullopt);

// Inputs:  face, a general face; actions, a whole sequence of it (as a report or a saved document
//          holds it); max_steps, reward and rules as it was made (face_step_general); policy, the name
//          the result reports; occt_blocks, as DecomposeSettings::occt_blocks.
// Outputs: the decomposition the sequence makes (region; block_faces and shape as decompose_input_face
//          gives them), without searching again. Throws InputError as face_step_general does, or when
//          the sequence leaves parts unfinished.
FaceDecomposition face_replay_general(const InputFace& face, const std::vector<RegionActionSpec>& actions,
                                      int max_steps, RewardPreset reward, const std::string& policy = "replay",
                                      bool occt_blocks = true, const std::optional<BlockRules>& rules = std::nullopt);

// Inputs:  face, cuts, step, max_steps and reward as for face_step; policy, a name of policy_names()
//          or a policy file (empty: the default).
// Outputs: the policy's value network's score at every model vertex of the part cut at that step,
//          in the order of face_step's vertices (a vertex scores the best of the candidate cuts through
//          it; -infinity when no candidate cut runs through it, e.g. lines only along the boundary).
// Throws InputError when the policy has no value network (a baseline), when no cut follows the step,
//          or as face_step does.
std::vector<double> face_vertex_scores(const InputFace& face, const std::vector<CutSpec>& cuts, int step,
                                       const std::string& policy, int max_steps = 0,
                                       RewardPreset reward = RewardPreset::Paper);

// face_vertex_scores for a general face: actions, step, max_steps, reward and rules as for
// face_step_general; policy, a lookahead agent's (sac-mesh, sac-paper, a policy file, or auto, whose
// scores are its learned fallback's). Outputs: one score per vertex of the part the next action cuts,
// in RegionSnapshot::vertices' order (the best Q of the policy's shortlisted actions from the
// vertex; -infinity where none starts). Throws InputError as face_vertex_scores does.
std::vector<double> face_vertex_scores_general(const InputFace& face, const std::vector<RegionActionSpec>& actions, int step,
                                               const std::string& policy, int max_steps = 0,
                                               RewardPreset reward = RewardPreset::Paper,
                                               const std::optional<BlockRules>& rules = std::nullopt);

struct FaceMesh {
  Decomposition decomposition;  // replayed from the cut sequence
  MeshResult result;
};

// Inputs:  face; cuts, its decomposition's whole cut sequence; max_steps and reward as the sequence
//          was made; options (size, fixed intervals; options.episode is set from max_steps, reward).
// Outputs: the decomposition and its quad mesh (see mesh_pipeline.h). Throws InputError when the
//          sequence does not belong to the face, the decomposition is incomplete or the request is
//          infeasible; std::runtime_error when the mesh fails the conformity check.
FaceMesh face_mesh(const InputFace& face, const std::vector<CutSpec>& cuts, int max_steps, RewardPreset reward,
                   MeshOptions options);

}  // namespace autoblock
