// Mesh one face in one call, whatever its kind: decompose it (face_actions.h) and mesh the blocks
// (mesh_pipeline.h). The CLI's `mesh` and the benchmarks call this.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/api/face_actions.h"
#include "core/mesh/mesh_pipeline.h"

namespace autoblock {

struct FaceMeshing {
  FaceDecomposition decomposition;  // decomposition (rectilinear) or region (general); no OCCT blocks
  MeshResult result;
  double seconds = 0.0;             // decomposition and meshing, wall time
  int attempts = 1;                 // a general face's decompositions tried (see mesh_input_face)
  double corner_fraction = kMeshCornerFraction;  // the block rules of the one kept (face_actions.h)
  int min_edge_intervals = 1;       // the intervals every model edge has at least (MeshOptions)
  int search_width = 4;             // the kept search's width (candidates expanded per part)
  bool cut_smooth_parts = false;    // the kept search's progress rule (SearchTry)
  bool divide_holes = true;         // the kept search divided parts with many holes first (hole_division.h)
  bool tight_ogrid = true;          // the kept search allowed tight O-grids (SearchTry)
  int tight_ogrids = 0;             // the kept decomposition's O-grids in tight cells (ogrid_template)
  double counted_seconds = 0.0;     // a general face's tries: their cost as counted (kTriesTimeLimits)
  bool general() const { return decomposition.general(); }
  const std::string& policy() const {
    return general() ? decomposition.region.policy : decomposition.decomposition.policy;
  }
  size_t blocks() const {
    return general() ? decomposition.region.finished.size() : decomposition.decomposition.blocks.size();
  }
};

// Inputs:  face, a checked face; settings (the policy and its options; occt_blocks is ignored: the
//          mesh pipeline replays the cuts itself); options (size, fixed intervals, quad limit; the
//          episode options are set from settings).
// Outputs: the decomposition and its mesh, returned even when the conformity check fails (the
//          caller reports it: FaceMeshing::result.conformity). A general face searched (auto,
//          search) is searched by the tries of kSearchTries in order, cheapest first (the last, without
//          tight O-grids, only where the best decomposition so far has one), until one's
//          mesh reaches kRetryBelow of the face's topology bound (topology_jacobian_bound: what its
//          corners, holes and arcs allow) on a block model other than the far feet's
//          (block_model.h: a try whose blocks admit no counts otherwise, which a later try may mesh
//          better); a try's mesh below it is meshed again with at least two intervals per model
//          edge; the conformal mesh with the best judged_jacobian is kept (mesh_quality.h: the
//          minimum scaled Jacobian, a mesh with a degenerate quad ranking below any without; attempts,
//          search_width, corner_fraction, cut_smooth_parts, tight_ogrid and min_edge_intervals say
//          what was kept; tight_ogrids counts its tight cells' O-grids). Each search has the time
//          limit (counted in work); once a try has meshed and the tries have cost kTriesTimeLimits
//          times it, no further try is made. A search whose blocks fail to mesh
//          (no interval counts for them, say: a rare web of templates whose sides' counts
//          contradict), or that leaves a part unfinished, is skipped. When every try fails, the
//          first try is made once more without dividing the parts with many holes first
//          (hole_division.h: its cells, each meshable, can join into a ring of blocks around a hole
//          whose counts contradict); the first failure is thrown when that fails too. Another
//          policy makes one decomposition; when its blocks do not mesh, the search's tries are made
//          instead (RegionDecomposition::fallback_from, fallback_reason; the report's
//          "policy_fallback"). A width set in settings makes the first try (the others follow,
//          those of that width and rules left out). A general face's OpenCASCADE model
//          (options.occt_model) is made of the kept blocks only.
// Throws InputError for a bad policy, reward or request (see decompose_input_face, mesh_decomposition).
//
// Why narrow searches first: the search's reward does not see every mesh defect, so searches of other
// widths and block rules give different decompositions whose meshes differ more than their rewards;
// several cheap searches find a good mesh sooner than one wide one. On the 200-face arc benchmark
// (BENCHMARKS.md, "Tries of a searched face") the first try, of width 2, is the one kept on most
// faces, at a fraction of the default width's time. The last try lets the search cut parts that only
// the usual template's fallback could finish (BlockRules::cut_smooth_parts: a wedge whose ends are
// rounded); as every try's rule it lost on more faces than it won (BENCHMARKS.md, "Parts with fewer
// than three corners").
constexpr double kRetryBelow = 0.85;
// No further try once a mesh is made and the tries have cost this many times the search's time limit
// (a face of hundreds of parts, each try's search capped and its blocks' intervals and replay slow).
// The cost is counted, not timed, so that a face meshes the same on every machine: each search's work
// at kSearchWorkPerSecond (region_search.h), each mesh made at kMeshSecondsPerQuad and its interval
// programs' simplex iterations at kSimplexSecondsPerRowIteration a row, what they took on the machine
// the figures were measured on (BENCHMARKS.md, "A budget in work"). The wall clock backs it
// (search_wall_backstop of that, region_search.h).
constexpr double kTriesTimeLimits = 3.0;
constexpr double kMeshSecondsPerQuad = 50e-6;
constexpr double kSimplexSecondsPerRowIteration = 20e-9;
struct SearchTry {
  int width;                      // candidates expanded per part (region_search.h; its default: 4)
  double corner_fraction;         // the block rules (face_actions.h)
  bool cut_smooth_parts = false;  // the progress rule (block.h, BlockRules::cut_smooth_parts)
  bool tight_ogrid = true;        // the O-grid in tight cells (block.h; RegionSearchOptions::tight_ogrid)
};
// The last try leaves tight O-grids out, and is made only when the best decomposition so far has one
// (else it would repeat the first): the search, valuing their few blocks, takes them where a hole near
// the face's edge is better cut to the edge. (Second, it cost the plates whose tries run out of time
// a try: 40 perforated plates 0.7854 -> 0.7735.)
constexpr SearchTry kSearchTries[] = {{2, kMeshCornerFraction}, {3, kMeshCornerFraction},
                                      {4, kMeshCornerFraction}, {4, 0.95},
                                      {4, 0.75},                {8, kMeshCornerFraction},
                                      {4, kMeshCornerFraction, true}, {2, kMeshCornerFraction, false, false}};
FaceMeshing mesh_input_face(const InputFace& face, const DecomposeSettings& settings, MeshOptions options);

// Inputs:  face, a general face; actions, a whole cut sequence of it (as the workbench stores it, see
//          face_replay_general); max_steps, reward and rules as it was made; options (size, fixed
//          intervals, smoothing; min_edge_intervals, as the decomposition says, RegionDecomposition).
// Outputs: its decomposition (replayed, not searched again) and mesh. Throws InputError as
//          face_replay_general does or when the request is infeasible; std::runtime_error when the
//          mesh fails the conformity check.
FaceMeshing face_mesh_general(const InputFace& face, const std::vector<RegionActionSpec>& actions, int max_steps,
                              RewardPreset reward, MeshOptions options,
                              const std::optional<BlockRules>& rules = std::nullopt);

// Inputs: input, the file name; meshing. Output: the JSON report (mesh_report.h).
nlohmann::json face_meshing_json(const std::string& input, const FaceMeshing& meshing);

// Inputs: meshing; title. Output: the picture of the blocks and the mesh (mesh_picture.h), SVG.
std::string face_meshing_svg(const FaceMeshing& meshing, const std::string& title);

}  // namespace autoblock
