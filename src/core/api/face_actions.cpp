#include "core/api/face_actions.h"

#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>

#include <TopoDS.hxx>

#include "core/api/face_meshing.h"
#include "core/api/policy_source.h"
#include "core/common/error.h"
#include "core/env/occt_replay.h"
#include "core/env/region_replay.h"
#include "core/geometry/occt_face.h"
#include "core/region/region_search.h"
#include "core/mesh/conformal_merge.h"

namespace autoblock {

InputFace check_face(const TopoDS_Face& face, const std::string& source) { return input_face_from_occt(face, source); }

std::vector<FaceSummary> shape_faces(const TopoDS_Shape& shape) { return list_faces(shape); }

InputFace check_shape_face(const TopoDS_Shape& shape, const std::string& source, int face_number,
                           const std::string& how_to_choose) {
  return input_face_from_occt(select_face(shape, source, face_number, how_to_choose),
                              face_source_name(source, face_number));
}

namespace {

namespace fs = std::filesystem;

// A trained policy for general faces, loaded once per file (and again when the file changes).
std::shared_ptr<LearnedPolicy> learned_general_policy(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, std::pair<fs::file_time_type, std::shared_ptr<LearnedPolicy>>> loaded;
  const std::string path = policy_file_path(name);  // InputError when unknown
  std::error_code ec;
  const fs::file_time_type written = fs::last_write_time(path, ec);
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = loaded[path];
  if (!slot.second || slot.first != written) slot = {written, learned_runtime().load_policy(path)};
  return slot.second;
}

// The general engine's policy by name: general_policy_names(), or a lookahead agent's trained policy
// (a shipped name or a policy file: region_lookahead_policy.h). own_reward: the preset it aims at
// (the search's mesh, a trained policy's own; unset for the other baselines).
std::unique_ptr<RegionPolicy> general_policy(const std::string& name, const PolicySettings& settings,
                                             std::optional<RewardPreset>* own_reward = nullptr) {
  if (name.empty() || name == "auto" || name == "search" || name == "optimal") {
    RegionSearchOptions options;
    options.time_limit = settings.general_time_limit > 0 ? settings.general_time_limit : 0.0;
    if (settings.general_search_width > 0) options.width = settings.general_search_width;
    options.divide_holes = settings.general_divide_holes;
    options.tight_ogrid = settings.general_tight_ogrid;
    if (own_reward) *own_reward = RewardPreset::Mesh;
    return std::make_unique<RegionSearchPolicy>(options);
  }
  if (name == "greedy") return std::make_unique<RegionGreedyPolicy>();
  if (name == "random" || name == "random-split") return std::make_unique<RegionRandomPolicy>(settings.seed);
  std::string list;
  for (const std::string& n : general_policy_names()) list += (list.empty() ? "" : ", ") + n;
  if (!is_baseline_name(name)) {
    const std::shared_ptr<LearnedPolicy> learned = learned_general_policy(name);
    std::unique_ptr<RegionPolicy> policy = learned->deployed_region_policy(name);
    if (!policy) {
      throw InputError("the policy '" + name + "' (the paper's agent, trained before it learned on general faces) "
                       "works on faces whose edges run along two perpendicular directions; this face has edges at "
                       "other angles: use one of " + list + " or a policy trained since (sac-mesh, sac-paper)");
    }
    if (own_reward) *own_reward = learned->reward();
    // The search's budget bounds a learned policy too: past it, greedy finishes the parts left.
    return std::make_unique<TimedRegionPolicy>(std::move(policy),
                                               settings.general_time_limit > 0 ? settings.general_time_limit : 0.0);
  }
  throw InputError("the policy '" + name + "' works on faces whose edges run along two perpendicular directions; "
                   "this face has edges at other angles: use one of " + list + " or a lookahead agent's policy");
}

RegionEpisodeOptions general_options(const InputFace& face, const std::string& what, int max_steps, RewardPreset reward,
                                     const std::optional<BlockRules>& rules) {
  if (!face.is_general()) {
    throw InputError(face.source + ": " + what + ": this face's edges run along two perpendicular directions, so its "
                     "cuts are given by vertex and axis, not by origin and direction");
  }
  RegionEpisodeOptions options;
  options.max_steps = max_steps;
  options.reward = reward;
  if (rules) {
    options.rules = *rules;
    options.face_rules = false;
  }
  return options;
}

// The faces in the model's coordinates.
std::vector<TopoDS_Face> to_model(std::vector<TopoDS_Face> faces, const Placement& frame) {
  if (frame.identity()) return faces;
  for (TopoDS_Face& f : faces) f = TopoDS::Face(shape_to_model(f, frame));
  return faces;
}

// Sets result's block faces (blocks, cut by OpenCASCADE in the face's frame) and their conformal merge.
void set_block_faces(FaceDecomposition& result, std::vector<TopoDS_Face> blocks) {
  const InputFace& face = result.face;
  result.block_faces = to_model(std::move(blocks), face.frame);
  result.shape = conformal_merge(result.block_faces, face.is_general() ? face.region.quantum() : 0.0).compound;
}

}  // namespace

FaceDecomposition decompose_input_face(const InputFace& face, const DecomposeSettings& settings) {
  check_reward_preset(settings.reward);
  FaceDecomposition result;
  result.face = face;
  std::vector<TopoDS_Face> blocks;
  if (face.is_general()) {
    std::optional<FaceMeshing> meshed;
    if (settings.mesh_tries) {
      // The decomposition `autoblock mesh` keeps (face_meshing.h): the search's tries, each meshed; another
      // policy's one decomposition, or the search's tries when its blocks do not mesh. When none
      // meshes (a reason of ours: blocks that admit no interval counts, a part left unfinished), the
      // policy's decomposition below, as it is: a decomposition can be shown even when it cannot be
      // meshed. (mesh_input_face decomposes with mesh_tries and occt_blocks off itself.)
      MeshOptions mesh;
      mesh.occt_model = false;
      try {
        meshed = mesh_input_face(face, settings, mesh);
      } catch (const InputError&) {
        throw;
      } catch (const std::exception&) {
        // no try meshed: the one search below
      }
    }
    if (meshed) {
      result.region = std::move(meshed->decomposition.region);
      result.region.seconds = meshed->seconds;  // every try's search and mesh
      if (settings.occt_blocks) {
        {
          const auto lock = lock_general_engine();
          blocks = replay_region_cuts_occt(face.occt, face.region, result.region, {}, &face.arcs);
        }
        set_block_faces(result, std::move(blocks));
      }
      return result;
    }
    std::optional<RewardPreset> own_reward;
    std::unique_ptr<RegionPolicy> policy = general_policy(settings.policy, settings.policy_settings, &own_reward);
    RegionEpisodeOptions options;
    options.max_steps = settings.max_steps;
    options.corner_fraction = settings.corner_fraction;
    options.cut_smooth_parts = settings.cut_smooth_parts;
    // The policy's own preset, as on the grid: mesh for auto and search, a trained policy's own, paper
    // for the other baselines.
    options.reward = !settings.reward.empty() ? reward_preset_by_name(settings.reward)
                                              : own_reward.value_or(RewardPreset::Paper);
    {
      const auto lock = lock_general_engine();
      result.region = decompose_region(face.region, *policy, options);
      if (settings.occt_blocks) blocks = replay_region_cuts_occt(face.occt, face.region, result.region, options, &face.arcs);
    }
  } else {
    PolicySettings policy_settings = settings.policy_settings;
    policy_settings.reward = settings.reward;  // what optimal maximises
    const auto source = policy_source(settings.policy, policy_settings);
    std::unique_ptr<Policy> policy = source->make(face.grid.size, settings.policy_settings.seed);
    EpisodeOptions options;
    options.max_steps = settings.max_steps;
    options.reward = settings.reward.empty() ? source->reward() : reward_preset_by_name(settings.reward);
    result.decomposition = decompose_face(face.grid, *policy, options);
    if (settings.occt_blocks) blocks = replay_cuts_occt(face.occt, face.grid, result.decomposition.cuts, options);
  }
  if (settings.occt_blocks) set_block_faces(result, std::move(blocks));
  return result;
}

EpisodeSnapshot face_step(const InputFace& face, const std::vector<CutSpec>& cuts, int step, int max_steps,
                          RewardPreset reward) {
  require_rectilinear(face, "stepping through a decomposition");
  EpisodeOptions options;
  options.max_steps = max_steps;
  options.reward = reward;
  return episode_snapshot(face.grid, cuts, step, options);
}

RegionSnapshot face_step_general(const InputFace& face, const std::vector<RegionActionSpec>& actions, int step,
                                 int max_steps, RewardPreset reward, const std::optional<BlockRules>& rules) {
  const RegionEpisodeOptions options = general_options(face, "stepping through a general sequence", max_steps, reward, rules);
  const auto lock = lock_general_engine();
  return region_snapshot(face.region, actions, step, options);
}

FaceDecomposition face_replay_general(const InputFace& face, const std::vector<RegionActionSpec>& actions,
                                      int max_steps, RewardPreset reward, const std::string& policy, bool occt_blocks,
                                      const std::optional<BlockRules>& rules) {
  const RegionEpisodeOptions options = general_options(face, "replaying a general sequence", max_steps, reward, rules);
  FaceDecomposition result;
  result.face = face;
  std::vector<TopoDS_Face> blocks;
  {
    const auto lock = lock_general_engine();
    result.region = replay_region_decomposition(face.region, actions, options, policy);
    if (occt_blocks) blocks = replay_region_cuts_occt(face.occt, face.region, result.region, options, &face.arcs);
  }
  if (occt_blocks) set_block_faces(result, std::move(blocks));
  return result;
}

std::vector<double> face_vertex_scores(const InputFace& face, const std::vector<CutSpec>& cuts, int step,
                                       const std::string& policy, int max_steps, RewardPreset reward) {
  require_rectilinear(face, "scoring vertices with a value network");
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

std::vector<double> face_vertex_scores_general(const InputFace& face, const std::vector<RegionActionSpec>& actions, int step,
                                               const std::string& policy, int max_steps, RewardPreset reward,
                                               const std::optional<BlockRules>& rules) {
  const RegionEpisodeOptions options = general_options(face, "scoring vertices with a value network", max_steps, reward, rules);
  const auto source = policy_source(policy, PolicySettings{});
  const std::shared_ptr<LearnedPolicy> scorer = source->scoring_policy();
  if (!scorer) {
    throw InputError("the policy '" + source->name() +
                     "' is a baseline: it has no value network, so there are no vertex scores");
  }
  const auto lock = lock_general_engine();
  const RegionEpisode episode = replay_region_episode(face.region, actions, step, options);
  if (!episode.running()) {
    throw InputError("no action follows step " + std::to_string(step) + ": the episode is over, there is no part to score");
  }
  const std::vector<float> scores = scorer->region_vertex_scores(episode);
  return std::vector<double>(scores.begin(), scores.end());
}

FaceMesh face_mesh(const InputFace& face, const std::vector<CutSpec>& cuts, int max_steps, RewardPreset reward,
                   MeshOptions options) {
  require_rectilinear(face, "meshing");
  options.episode.max_steps = max_steps;
  options.episode.reward = reward;
  FaceMesh out;
  out.decomposition = replay_decomposition(face.grid, cuts, options.episode, "replay");
  out.result = mesh_decomposition(face, out.decomposition, options);
  require_conformal(out.result);
  return out;
}

}  // namespace autoblock
