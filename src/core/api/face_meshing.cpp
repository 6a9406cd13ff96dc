#include "core/api/face_meshing.h"

#include <chrono>

#include "core/mesh/mesh_picture.h"
#include "core/mesh/mesh_report.h"

namespace autoblock {

FaceMeshing mesh_input_face(const InputFace& face, const DecomposeSettings& settings, MeshOptions options) {
  const auto start = std::chrono::steady_clock::now();
  DecomposeSettings decompose = settings;
  decompose.occt_blocks = false;
  FaceMeshing out;
  out.decomposition = decompose_input_face(face, decompose);
  if (face.is_general()) {
    const RegionDecomposition& d = out.decomposition.region;
    options.general.max_steps = settings.max_steps;
    options.general.reward = d.reward;
    out.result = mesh_region_decomposition(face, d, options);
  } else {
    const Decomposition& d = out.decomposition.decomposition;
    options.episode.max_steps = settings.max_steps;
    options.episode.reward = d.reward;
    out.result = mesh_decomposition(face, d, options);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

FaceMeshing face_mesh_general(const InputFace& face, const std::vector<RegionActionSpec>& actions, int max_steps,
                              RewardPreset reward, MeshOptions options) {
  const auto start = std::chrono::steady_clock::now();
  FaceMeshing out;
  out.decomposition = face_replay_general(face, actions, max_steps, reward, "replay", false);
  options.general.max_steps = max_steps;
  options.general.reward = reward;
  out.result = mesh_region_decomposition(face, out.decomposition.region, options);
  require_conformal(out.result);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

nlohmann::json face_meshing_json(const std::string& input, const FaceMeshing& m) {
  return m.general() ? mesh_report_json(input, m.decomposition.region, m.result, m.seconds)
                     : mesh_report_json(input, m.decomposition.decomposition, m.result, m.seconds);
}

std::string face_meshing_svg(const FaceMeshing& m, const std::string& title) {
  const InputFace& face = m.decomposition.face;
  if (!m.general()) return mesh_svg(face.planar.polygon, m.decomposition.decomposition.blocks, m.result.mesh, title);
  std::vector<Ring> parts;
  for (const FinishedRegion& f : m.decomposition.region.finished) parts.push_back(f.region.outer());
  return mesh_svg(face.region.loops(), parts, m.result.mesh, title);
}

}  // namespace autoblock
