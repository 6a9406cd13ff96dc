#include "core/api/face_meshing.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/common/error.h"
#include "core/mesh/mesh_picture.h"
#include "core/mesh/mesh_quality.h"
#include "core/mesh/mesh_report.h"
#include "core/region/region_search.h"

namespace autoblock {

FaceMeshing mesh_input_face(const InputFace& face, const DecomposeSettings& settings, MeshOptions options) {
  const auto start = std::chrono::steady_clock::now();
  DecomposeSettings decompose = settings;
  decompose.occt_blocks = false;
  decompose.mesh_tries = false;  // the tries are made here
  FaceMeshing out;
  if (!face.is_general()) {
    out.decomposition = decompose_input_face(face, decompose);
    const Decomposition& d = out.decomposition.decomposition;
    options.episode.max_steps = settings.max_steps;
    options.episode.reward = d.reward;
    out.result = mesh_decomposition(face, d, options);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  }
  // The OpenCASCADE model, if wanted, of the kept decomposition only (not of every try).
  const bool occt_model = options.occt_model;
  options.occt_model = false;
  options.general.max_steps = settings.max_steps;
  // The tries: kSearchTries, the first with the settings' block rules and width if set (the others
  // as listed, that one left out). A policy other than the search makes one decomposition, meshed once.
  const int set_width = settings.policy_settings.general_search_width;
  std::vector<SearchTry> tries{{set_width > 0 ? set_width : kSearchTries[0].width, settings.corner_fraction,
                                settings.cut_smooth_parts, settings.policy_settings.general_tight_ogrid}};
  for (const SearchTry& t : kSearchTries) {
    if (t.width != tries[0].width || t.corner_fraction != tries[0].corner_fraction ||
        t.cut_smooth_parts != tries[0].cut_smooth_parts || t.tight_ogrid != tries[0].tight_ogrid) {
      tries.push_back(t);
    }
  }
  auto finish = [&] {
    if (occt_model) {
      const auto replay_start = std::chrono::steady_clock::now();
      out.result.model = region_occt_model(face, out.decomposition.region, options);
      out.result.merge_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - replay_start).count();
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // Measured against the topology bound (block.h), not the corners' alone: a disk, a fillet or a
  // round hole caps every mesh of the face below its corner bound, and a try cannot beat that.
  auto ratio = [](const MeshResult& r) {
    return r.conformity.conformal ? judged_jacobian(r.quality) / r.topology_bound : -1e300;
  };
  // A decomposition's O-grids in tight cells (block.h).
  auto tight_ogrids = [](const RegionDecomposition& d) {
    int count = 0;
    for (const FinishedRegion& f : d.finished) count += f.is_template && tight_ogrid_template(f.region, d.rules);
    return count;
  };
  bool have = false;  // a try has meshed (out.result is its mesh)
  std::string fallback_from, fallback_reason;  // another policy's blocks that did not mesh
  std::exception_ptr first_error;
  out.attempts = 0;
  auto decompose_try = [&](size_t k) {
    decompose.corner_fraction = tries[k].corner_fraction;
    decompose.cut_smooth_parts = tries[k].cut_smooth_parts;
    decompose.policy_settings.general_tight_ogrid = tries[k].tight_ogrid;
    decompose.policy_settings.general_search_width = tries[k].width;
    // (The replay takes its block rules from the decomposition: no options to change for it.)
    ++out.attempts;
    return decompose_input_face(face, decompose);
  };
  std::optional<FaceDecomposition> first = decompose_try(0);
  if (first->region.policy != "search") {
    // Another policy: its one decomposition, meshed. When its blocks do not mesh (a reason of ours:
    // no interval counts for them, or a mesh that fails its own conformity check: quads inverted in
    // a greedy policy's sliver), the search's tries mesh the face instead, and say so.
    options.general.reward = first->region.reward;
    try {
      out.result = mesh_region_decomposition(face, first->region, options);
      require_conformal(out.result);
      out.decomposition = std::move(*first);
      out.corner_fraction = settings.corner_fraction;
      finish();
      return out;
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      fallback_from = first->region.policy;
      fallback_reason = e.what();
      decompose.policy = "search";
      first.reset();
    }
  }
  const double time_limit = settings.policy_settings.general_time_limit;
  // The tries' cost, counted (kTriesTimeLimits): their searches' work, their meshes' quads and their
  // interval programs' simplex work.
  long long search_work = 0, quads = 0, simplex_work = 0;
  options.simplex_work = &simplex_work;
  auto spent = [&] {
    return static_cast<double>(search_work) / kSearchWorkPerSecond + kMeshSecondsPerQuad * static_cast<double>(quads) +
           kSimplexSecondsPerRowIteration * static_cast<double>(simplex_work);
  };
  // When no try meshed, a second pass: the first try once more, without the hole division.
  for (int pass = 0; pass < 2 && !have; ++pass) {
    if (pass == 1) {
      if (!settings.policy_settings.general_divide_holes) break;
      decompose.policy_settings.general_divide_holes = false;
      tries.resize(1);
    }
    for (size_t k = 0; k < tries.size(); ++k) {
      // (A mesh on the far feet's block model, FeetSnap::far, is of a try whose blocks admit no counts
      // otherwise: it ends no tries. Where it did, a 16-hole flange kept its first try's 0.894 in
      // 0.22 s, not its third's 0.929 in 1.16 s, and a plate of holes 0.873 against 0.905.)
      if (have && ratio(out.result) >= kRetryBelow && !out.result.block_model.far_feet()) break;
      // A face whose searches run out of time (hundreds of parts: a plate with scores of holes) has
      // spent what further tries would: the mesh made stands. What the tries cost is counted, not
      // timed (so that a face meshes the same on every machine); the wall clock only backs it.
      if (have && time_limit > 0.0 &&
          (spent() > kTriesTimeLimits * time_limit ||
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
               search_wall_backstop(kTriesTimeLimits * time_limit))) {
        break;
      }
      // A try without tight O-grids after one whose kept decomposition has none would repeat it.
      if (have && !tries[k].tight_ogrid && tries[0].tight_ogrid && out.tight_ogrids == 0) continue;
      FaceDecomposition again = pass == 0 && k == 0 && first ? std::move(*first) : decompose_try(k);
      search_work += again.region.work;
      options.general.reward = again.region.reward;
      if (!again.region.complete() && (have || k + 1 < tries.size() || first_error)) {
        // A try that leaves a part unfinished (under other block rules the fallback may find no cut
        // that makes progress on some part) is no mesh: another try may do better. The last one, with
        // nothing meshed, is meshed below as it is (mesh_region_decomposition says what is wrong).
        continue;
      }
      MeshResult meshed;
      try {
        meshed = mesh_region_decomposition(face, again.region, options);
        quads += static_cast<long long>(meshed.mesh.quads.size());
      } catch (const InputError&) {
        throw;
      } catch (const std::exception&) {
        // This try's blocks failed to mesh (a reason of ours: blocks that admit no interval counts,
        // say): the other tries may mesh the face; if none does, the first failure is the answer.
        if (!first_error) first_error = std::current_exception();
        continue;
      }
      int min_edge_intervals = options.min_edge_intervals;
      // A poor mesh: the same blocks with at least two intervals on every model edge (a small block one
      // element across, meshed corner to corner through its side vertices, is what holds the minimum
      // down then; more elements there lift it). Skipped when the user's counts or the quad limit
      // forbid it.
      if (ratio(meshed) < kRetryBelow && options.min_edge_intervals < 2) {
        MeshOptions finer = options;
        finer.min_edge_intervals = 2;
        // Two intervals per edge are what the twisted rounds would give the thin parts: a retry
        // with inverted quads is not made again (each round solves the whole interval program again,
        // seconds on a face of thousands of edges) and loses to the first mesh.
        finer.twisted_rounds = 0;
        try {
          MeshResult fine = mesh_region_decomposition(face, again.region, finer);
          quads += static_cast<long long>(fine.mesh.quads.size());
          if (ratio(fine) > ratio(meshed)) {
            meshed = std::move(fine);
            min_edge_intervals = 2;
          }
        } catch (const std::exception&) {
          // infeasible with the fixed counts, too many quads, or no counts at all: the mesh stays
        }
      }
      if (!have || ratio(meshed) > ratio(out.result)) {
        out.decomposition = std::move(again);
        out.result = std::move(meshed);
        out.corner_fraction = tries[k].corner_fraction;
        out.search_width = tries[k].width;
        out.cut_smooth_parts = tries[k].cut_smooth_parts;
        out.min_edge_intervals = min_edge_intervals;
        out.divide_holes = decompose.policy_settings.general_divide_holes;
        out.tight_ogrid = tries[k].tight_ogrid;
        out.tight_ogrids = tight_ogrids(out.decomposition.region);
        have = true;
      }
    }
  }
  if (!have) {
    if (first_error) std::rethrow_exception(first_error);
    throw std::logic_error("mesh_input_face: no try meshed and none failed");
  }
  out.counted_seconds = spent();
  out.decomposition.region.min_edge_intervals = out.min_edge_intervals;
  out.decomposition.region.fallback_from = fallback_from;
  out.decomposition.region.fallback_reason = fallback_reason;
  finish();
  return out;
}

FaceMeshing face_mesh_general(const InputFace& face, const std::vector<RegionActionSpec>& actions, int max_steps,
                              RewardPreset reward, MeshOptions options, const std::optional<BlockRules>& rules) {
  const auto start = std::chrono::steady_clock::now();
  FaceMeshing out;
  out.decomposition = face_replay_general(face, actions, max_steps, reward, "replay", false, rules);
  out.decomposition.region.min_edge_intervals = out.min_edge_intervals = std::max(1, options.min_edge_intervals);
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
  report["cut_smooth_parts"] = m.cut_smooth_parts;
  report["min_edge_intervals"] = m.min_edge_intervals;
  report["search_width"] = m.search_width;
  report["divide_holes"] = m.divide_holes;
  report["tight_ogrid"] = m.tight_ogrid;
  report["tight_ogrids"] = m.tight_ogrids;
  if (m.counted_seconds > 0.0) report["counted_seconds"] = m.counted_seconds;
  const RegionDecomposition& d = m.decomposition.region;
  if (!d.fallback_from.empty()) report["policy_fallback"] = {{"policy", d.fallback_from}, {"reason", d.fallback_reason}};
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
