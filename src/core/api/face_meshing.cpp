#include "core/api/face_meshing.h"

#include <chrono>
#include <exception>

#include "core/common/error.h"
#include "core/mesh/mesh_picture.h"
#include "core/mesh/mesh_report.h"
#include "core/region/region_search.h"

namespace autoblock {

FaceMeshing mesh_input_face(const InputFace& face, const DecomposeSettings& settings, MeshOptions options) {
  const auto start = std::chrono::steady_clock::now();
  DecomposeSettings decompose = settings;
  decompose.occt_blocks = false;
  FaceMeshing out;
  out.corner_fraction = settings.corner_fraction;
  out.search_width = settings.policy_settings.general_search_width > 0 ? settings.policy_settings.general_search_width
                                                                       : RegionSearchOptions{}.width;
  out.decomposition = decompose_input_face(face, decompose);
  if (face.is_general()) {
    // The OpenCASCADE model, if wanted, of the kept decomposition only (not of every attempt).
    const bool occt_model = options.occt_model;
    options.occt_model = false;
    options.general.max_steps = settings.max_steps;
    options.general.reward = out.decomposition.region.reward;
    const bool searched = out.decomposition.region.policy == "search";
    // The search's first mesh failing for a reason of ours (blocks that admit no interval counts, say)
    // is not the end: the other tries below may mesh the face; if none does, that error is the answer
    // (set while no try has meshed).
    std::exception_ptr first_error;
    try {
      out.result = mesh_region_decomposition(face, out.decomposition.region, options);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception&) {
      if (!searched) throw;
      first_error = std::current_exception();
    }
    // A poor mesh from the search: other block rules may do better (a face whose good blocks need
    // corners just outside the rules, or whose rules forbid the cut that matters).
    // Measured against the topology bound (block.h), not the corners' alone: a disk, a fillet or a
    // round hole caps every mesh of the face below its corner bound, and a try cannot beat that.
    auto ratio = [](const MeshResult& r) {
      return r.conformity.conformal ? r.quality.min_scaled_jacobian / r.topology_bound : -1e300;
    };
    for (const SearchRetry& retry_with : kSearchRetries) {
      if (!searched || (!first_error && ratio(out.result) >= kRetryBelow)) break;
      const double fraction = retry_with.corner_fraction;
      decompose.corner_fraction = fraction;
      decompose.policy_settings.general_search_width = retry_with.width;
      // (The replay takes its block rules from the decomposition: no options to change for it.)
      FaceDecomposition again = decompose_input_face(face, decompose);
      ++out.attempts;
      // Another try that leaves a part unfinished (under other block rules the fallback may find no
      // cut that makes progress on some part) is no mesh: the one kept stands.
      if (!again.region.complete()) continue;
      MeshResult meshed;
      try {
        meshed = mesh_region_decomposition(face, again.region, options);
      } catch (const InputError&) {
        throw;
      } catch (const std::exception&) {
        continue;  // this try's blocks failed to mesh: the mesh kept stands
      }
      if (first_error || ratio(meshed) > ratio(out.result)) {
        first_error = nullptr;
        out.decomposition = std::move(again);
        out.result = std::move(meshed);
        out.corner_fraction = fraction;
        out.search_width = retry_with.width;
      }
    }
    // Still poor: the kept blocks meshed with at least two intervals on every model edge (a small
    // block one element across, meshed corner to corner through its side vertices, is what holds the
    // minimum down then; more elements there lift it). Skipped when the user's counts or the quad
    // limit forbid it.
    if (first_error) std::rethrow_exception(first_error);
    if (searched && ratio(out.result) < kRetryBelow && options.min_edge_intervals < 2) {
      MeshOptions finer = options;
      finer.min_edge_intervals = 2;
      try {
        MeshResult meshed = mesh_region_decomposition(face, out.decomposition.region, finer);
        ++out.attempts;
        if (ratio(meshed) > ratio(out.result)) {
          out.result = std::move(meshed);
          out.min_edge_intervals = 2;
        }
      } catch (const std::exception&) {
        // infeasible with the fixed counts, too many quads, or no counts at all: the mesh stays as it is
      }
    }
    if (occt_model) {
      const auto replay_start = std::chrono::steady_clock::now();
      out.result.model = region_occt_model(face, out.decomposition.region, options);
      out.result.merge_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - replay_start).count();
    }
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
  if (!m.general()) return mesh_report_json(input, m.decomposition.decomposition, m.result, m.seconds);
  nlohmann::json report = mesh_report_json(input, m.decomposition.region, m.result, m.seconds);
  report["attempts"] = m.attempts;
  report["corner_fraction"] = m.corner_fraction;
  report["min_edge_intervals"] = m.min_edge_intervals;
  report["search_width"] = m.search_width;
  return report;
}

std::string face_meshing_svg(const FaceMeshing& m, const std::string& title) {
  const InputFace& face = m.decomposition.face;
  if (!m.general()) return mesh_svg(face.planar.polygon, m.decomposition.decomposition.blocks, m.result.mesh, title);
  std::vector<Ring> parts;
  for (const FinishedRegion& f : m.decomposition.region.finished) parts.push_back(f.region.outer());
  return mesh_svg(face.region.loops(), parts, m.result.mesh, title);
}

}  // namespace autoblock
