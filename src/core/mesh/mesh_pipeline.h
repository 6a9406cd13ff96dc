// From a decomposition to a checked quad mesh: replay the cuts on the CAD face, merge the blocks
// conformally, assign intervals, mesh every block, measure quality and check conformity. A
// rectilinear face's decomposition (the grid engine) is meshed on strips (strip_layout.h), every
// element an exact rectangle; a general face's (core/region) on its block model (block_model.h,
// edge_intervals.h, block_mesh.h).
#pragma once

#include <vector>

#include "core/env/decomposition.h"
#include "core/io/input_face.h"
#include "core/mesh/block_model.h"
#include "core/mesh/conformal_merge.h"
#include "core/mesh/interval_assignment.h"
#include "core/mesh/mesh_conformity.h"
#include "core/mesh/mesh_quality.h"
#include "core/mesh/mesh_smoothing.h"
#include "core/mesh/quad_mesh.h"
#include "core/mesh/strip_layout.h"

namespace autoblock {

// A user's fixed interval count on the stretch from a to b (see fixed_intervals_on).
struct EdgeIntervals {
  Point2 a, b;
  int intervals = 1;
};

// Smoothing sweeps on a general face's mesh by default (a rectilinear face's elements are exact
// rectangles: nothing to smooth).
constexpr int kDefaultSmoothingSweeps = 30;

// A general face's mesh below this fraction of its topology bound (block.h) that has a convex arc is
// made a second time with the arcs' chord steps as targets, not minima (mesh_region_decomposition).
constexpr double kArcTargetsBelow = 0.85;

constexpr int kTwistedRounds = 3;
// A general face's mesh with inverted quads after the twisted rounds and the fill by length: the quads
// within this many rings of them get up to this many more sweeps of smoothing on their own
// (untangle_quad_mesh, mesh_smoothing.h).
constexpr int kUntangleRings = 10;
constexpr int kUntangleSweeps = 300;

struct MeshOptions {
  double size = 0.0;                 // target element size h; 0: the face's size / kDefaultSizeDivisions
  std::vector<EdgeIntervals> fixed;  // fixed interval counts
  long max_quads = kMaxMeshQuads;
  EpisodeOptions episode;            // the decomposition's options (for the replay)
  RegionEpisodeOptions general;      // a general face's decomposition options (replay, block rules)
  int smoothing_sweeps = kDefaultSmoothingSweeps;  // a general face's mesh (mesh_smoothing.h); 0: none
  int min_edge_intervals = 1;        // a general face's model edges: at least this many intervals each
  // A general face: replay the cuts with OpenCASCADE and merge the parts into MeshResult::model (what
  // the hex sweep builds on). Its mesh is made from the block model and checked on its own (the
  // conformity check against the face's loops), so meshing a face alone can leave this off.
  bool occt_model = true;
  // A general face's poor mesh with a convex arc is made again with the arcs' chord steps as targets
  // (kArcTargetsBelow, MeshResult::arc_targets); false: not.
  bool arc_targets = true;
  // A general face's poor mesh with a template part that the two-corner template finishes better is
  // made again with it there (MeshResult::two_corner); false: not.
  bool two_corner = true;
  // A general face's parts with a twisted (inverted) quad: how many times their edges' counts are
  // doubled and the mesh made again (mesh_pipeline.cpp); 0: the mesh stands as first made.
  int twisted_rounds = kTwistedRounds;
  // A general face's: if set, every interval program's simplex work is added to it
  // (IntervalOptions::simplex_work).
  long long* simplex_work = nullptr;
};

struct MeshResult {
  ConformalBlocks model;        // the blocks merged, sharing edges (a general face: if MeshOptions::occt_model)
  StripLayout layout;           // a rectilinear face's strips
  BlockModel block_model;       // a general face's block model
  std::vector<FixedIntervals> fixed;  // the user's fixed counts, as strips (rectilinear) or model edges (general)
  IntervalAssignment intervals; // per strip (rectilinear) or per model edge (general)
  QuadMesh mesh;
  MeshQuality quality;
  Conformity conformity;        // the independent check
  bool default_size = false;    // h was derived from the face's size
  double bound = 1.0;           // scaled_jacobian_bound of the face (1 for a rectilinear face)
  double topology_bound = 1.0;  // topology_jacobian_bound of the face (block.h: its holes and smooth loops too)
  SmoothingReport smoothing;    // a general face's
  double merge_seconds = 0.0;   // replay of the cuts and the conformal merge (OpenCASCADE)
  double interval_seconds = 0.0;
  double mesh_seconds = 0.0;    // mapped meshing
  double check_seconds = 0.0;   // quality and conformity
  // A general face's: the mesh kept was made with the arcs' chord steps as the interval program's
  // targets rather than its minima (mesh_region_decomposition).
  bool arc_targets = false;
  // A general face's: the mesh kept was made with the two-corner template on the parts where it beats
  // the template's default pieces (block.h, two_corner_improves; mesh_region_decomposition).
  bool two_corner = false;
  // A general face's: the mesh kept was made with finer intervals on the arcs' edges from acute tips
  // (a convex corner sharper than 60 degrees where an arc ends; mesh_region_decomposition).
  bool acute_tips = false;
  // A general face's: the mesh kept is of the block model made with the wider tolerance, the first's
  // having failed its conformity check (kWideModelToleranceQuanta; mesh_region_decomposition).
  bool wide_tolerance = false;
};

// Inputs:  face; decomposition of it (complete); options.
// Outputs: everything above. The mesh is returned even when the conformity check fails (the
//          caller reports it).
// Throws InputError when the decomposition is incomplete or the request is infeasible (see
// assign_intervals, fixed_intervals_on); std::logic_error / std::runtime_error on internal failures.
MeshResult mesh_decomposition(const InputFace& face, const Decomposition& decomposition, const MeshOptions& options = {});

// Inputs:  face, a general face; decomposition of face.region (complete), made with options.general.
// Outputs: the cuts replayed on the face with OpenCASCADE, checked against the engine's parts, and
//          merged into one conformal model (what MeshResult::model holds when options.occt_model).
// Throws std::logic_error when the replay disagrees with the engine.
ConformalBlocks region_occt_model(const InputFace& face, const RegionDecomposition& decomposition, const MeshOptions& options);

// Inputs:  face, a general face; tolerance_quanta, its block model's (kModelToleranceQuanta, or
//          kWideModelToleranceQuanta where the first model's mesh failed its check: MeshResult::wide_tolerance).
// Output:  how far a node may lie off the face's boundary and off a block's side in the conformity
//          check (and the hex sweep's, of a cap): that many quanta, at least the face's own tolerance
//          and 1e-9 of its size.
double general_mesh_tolerance(const InputFace& face, double tolerance_quanta);

// Inputs:  face, a general face; decomposition of face.region (complete), made with options.general;
//          options.
// Outputs: everything above (layout empty; block_model, and fixed counts over its edges). Nodes lie
//          on the face's lattice (within its quantum), and conformity is checked to kModelToleranceQuanta quanta;
//          where that mesh fails the check, the block model is made again with kWideModelToleranceQuanta
//          (block_model.h), and that mesh, checked to it, is kept when it passes (wide_tolerance).
// Throws as mesh_decomposition.
MeshResult mesh_region_decomposition(const InputFace& face, const RegionDecomposition& decomposition,
                                     const MeshOptions& options = {});

// Inputs: result. Throws std::runtime_error ("the mesh failed the conformity check: ...") when the
// independent check failed.
void require_conformal(const MeshResult& result);

// Inputs: face; size as given (<= 0: none). Output: the target size h used.
double target_size_for(const InputFace& face, double size);

}  // namespace autoblock
