#include "core/mesh/mesh_pipeline.h"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/env/occt_replay.h"
#include "core/env/region_replay.h"
#include "core/geometry/occt_face.h"
#include "core/mesh/block_mesh.h"
#include "core/mesh/edge_intervals.h"
#include "core/mesh/mapped_mesh.h"

namespace autoblock {
namespace {

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The face to replay the cuts on: the input face, or, when it has flat vertices (where two collinear
// edges meet, as a face of a conformal compound has where a neighbour's edge ends), the validated
// polygon it stands for (flat vertices merged, corners on the grid): the grid mesher puts nodes on
// the grid of the face's corners only, so a flat vertex would be a model vertex between nodes.
TopoDS_Face face_to_replay(const InputFace& face) {
  size_t corners = face.planar.polygon.outer.size();
  for (const Ring& hole : face.planar.polygon.holes) corners += hole.size();
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(face.occt, TopAbs_VERTEX, vertices);
  if (static_cast<size_t>(vertices.Extent()) <= corners) return face.occt;
  return occt_face_from_polygon(face.planar.polygon, face.planar.z, face.planar.normal_up);
}

// The face's box from its vertices.
Box vertex_box(const TopoDS_Face& face) {
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
  Box box{1e300, 1e300, -1e300, -1e300};
  for (int v = 1; v <= vertices.Extent(); ++v) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
    box.xmin = std::min(box.xmin, p.X());
    box.ymin = std::min(box.ymin, p.Y());
    box.xmax = std::max(box.xmax, p.X());
    box.ymax = std::max(box.ymax, p.Y());
  }
  return box;
}

// The target size h for options.size (checked), noting in result whether it is the default.
double checked_target_size(const InputFace& face, const MeshOptions& options, MeshResult& result) {
  if (!std::isfinite(options.size) || options.size < 0) throw InputError("the element size must be a positive number");
  result.default_size = !(options.size > 0);
  return target_size_for(face, options.size);
}

// The user's fixed counts made by fix (per stretch), then the assignment by assign, into result. A
// second pass (a better mesh tried where a first one stands) gives GLPK kIntervalQuickIterations
// simplex iterations to find counts: a program with none by then is given up (std::runtime_error),
// not given 30 s more (a 1 000-edge disk's arc targets: 30 s for nothing, and the face's first mesh
// lost with them).
template <class Fix, class Assign>
void assign_with_fixed(MeshResult& result, const MeshOptions& options, double h, Fix fix, Assign assign,
                       const std::vector<int>& edge_minimum = {}, const std::vector<double>& edge_target = {},
                       bool second_pass = false) {
  IntervalOptions interval_options;
  if (second_pass) interval_options.first_iterations = kIntervalQuickIterations;
  interval_options.target_size = h;
  interval_options.simplex_work = options.simplex_work;
  interval_options.max_quads = options.max_quads;
  interval_options.min_intervals = options.min_edge_intervals;
  interval_options.edge_minimum = edge_minimum;
  interval_options.edge_target = edge_target;
  for (const EdgeIntervals& e : options.fixed) interval_options.fixed.push_back(fix(e));
  result.fixed = interval_options.fixed;
  result.intervals = assign(interval_options);
}

// Inputs: mesh; parts (nullptr, or one flag per part of the decomposition). Output: the number of
//         quads with a scaled Jacobian <= 0; each one's part flagged in *parts.
int inverted_quads(const QuadMesh& mesh, std::vector<char>* parts) {
  int count = 0;
  for (size_t k = 0; k < mesh.quads.size(); ++k) {
    if (quad_scaled_jacobian(mesh.corners(k)) > 0.0) continue;
    ++count;
    if (parts) (*parts)[static_cast<size_t>(mesh.quad_block[k])] = 1;
  }
  return count;
}

// A general face's interval counts of model into r, each model edge at least its edge_minimum, arcs
// aiming at edge_target (IntervalOptions).
void assign_arc_intervals(MeshResult& r, const BlockModel& model, const MeshOptions& options, double h, double tolerance,
                          const std::vector<int>& edge_minimum, const std::vector<double>& edge_target,
                          bool second_pass = false) {
  assign_with_fixed(r, options, h, [&](const EdgeIntervals& e) {
    return fixed_edge_intervals(model, e.a, e.b, e.intervals, tolerance);
  }, [&](const IntervalOptions& o) { return assign_edge_intervals(model, o); }, edge_minimum, edge_target, second_pass);
}

// r's mesh and smoothing from model and r's intervals (assign_arc_intervals, with edge_minimum and
// edge_target), twisted and folded parts made again as below (second_pass: as assign_with_fixed's).
void mesh_blocks(MeshResult& r, const BlockModel& model, const InputFace& face, const RegionDecomposition& d,
                 const MeshOptions& options, double h, double tolerance, std::vector<int> edge_minimum,
                 const std::vector<double>& edge_target, bool second_pass = false, const ArcEndGrading* graded = nullptr) {
  r.mesh = block_model_mesh(model, r.intervals.intervals, face.planar.z, &face.arcs, nullptr, graded);
  r.smoothing = smooth_quad_mesh(r.mesh, options.smoothing_sweeps, kWorstRounds, &face.arcs, face.straight_vertices);
  // A thin part whose two long sides have their vertices at different places along it gets a twisted
  // (inverted) quad when those sides carry few intervals, each vertex being a node: up to
  // options.twisted_rounds times (kTwistedRounds), the edges of the parts with an inverted quad get
  // twice their count as a minimum, and intervals and mesh are made again (stopping where the quad
  // limit or fixed counts forbid it).
  for (int round = 0; round < options.twisted_rounds; ++round) {
    std::vector<char> twisted(d.finished.size(), 0);
    if (inverted_quads(r.mesh, &twisted) == 0) break;
    for (const ModelBlock& block : model.blocks) {
      if (!twisted[static_cast<size_t>(block.part)]) continue;
      for (const ModelSide& side : block.sides) {
        for (const int e : side.edges) {
          edge_minimum[static_cast<size_t>(e)] = std::max(edge_minimum[static_cast<size_t>(e)], 2 * r.intervals.intervals[static_cast<size_t>(e)]);
        }
      }
    }
    // assign_with_fixed changes r's intervals only when the assignment succeeds.
    try {
      assign_arc_intervals(r, model, options, h, tolerance, edge_minimum, edge_target, second_pass);
    } catch (const InputError&) {
      break;  // too many quads, or the fixed counts forbid more: the mesh stays as it is
    }
    r.mesh = block_model_mesh(model, r.intervals.intervals, face.planar.z, &face.arcs, nullptr, graded);
    r.smoothing = smooth_quad_mesh(r.mesh, options.smoothing_sweeps, kWorstRounds, &face.arcs, face.straight_vertices);
  }
  // A fold that finer intervals do not undo (opposite sides spacing their nodes differently: a long
  // side with a fillet facing a short arc): those parts' blocks are filled along their sides' lengths
  // (transfinite_grid_by_length), kept if that leaves fewer inverted quads.
  std::vector<char> folded(d.finished.size(), 0);
  if (const int before = inverted_quads(r.mesh, &folded); before > 0) {
    std::vector<char> by_length(model.blocks.size(), 0);
    for (size_t b = 0; b < by_length.size(); ++b) by_length[b] = folded[static_cast<size_t>(model.blocks[b].part)];
    QuadMesh again = block_model_mesh(model, r.intervals.intervals, face.planar.z, &face.arcs, &by_length, graded);
    const SmoothingReport smoothing =
        smooth_quad_mesh(again, options.smoothing_sweeps, kWorstRounds, &face.arcs, face.straight_vertices);
    if (inverted_quads(again, nullptr) < before) {
      r.mesh = std::move(again);
      r.smoothing = smoothing;
    }
  }
  // Inverted quads left (a sliver's template, a time-capped search's late cuts): the smoothing goes on
  // about them alone (the first had stopped at its limit, each sweep lifting the worst a little).
  if (options.smoothing_sweeps > 0) untangle_quad_mesh(r.mesh, kUntangleRings, kUntangleSweeps);
}

}  // namespace

void require_conformal(const MeshResult& result) {
  if (!result.conformity.conformal) {
    throw std::runtime_error("the mesh failed the conformity check: " + result.conformity.problem);
  }
}

double target_size_for(const InputFace& face, double size) {
  if (size > 0) return size;
  return (face.is_general() ? face.region.bbox().longer_side() : face.grid.size) / kDefaultSizeDivisions;
}

MeshResult mesh_decomposition(const InputFace& face, const Decomposition& d, const MeshOptions& options) {
  require_rectilinear(face, "meshing");
  if (!d.complete()) {
    const size_t left = d.unfinished.size();
    throw InputError("the decomposition is incomplete (" + counted(static_cast<long long>(left), "part") +
                     (left == 1 ? " is not a rectangle" : " are not rectangles") + " after " +
                     counted(static_cast<long long>(d.cuts.size()), "cut") + "); meshing needs rectangles only: raise --max-steps or use another policy");
  }
  MeshResult result;
  const double h = checked_target_size(face, options, result);

  // Intervals first: an infeasible request fails before the slower CAD work.
  auto start = std::chrono::steady_clock::now();
  result.layout = strip_layout(face.grid, d.blocks, face.straight_vertices);
  const double tolerance = std::max(face.planar.tolerance, 1e-9 * face.grid.size);
  assign_with_fixed(result, options, h, [&](const EdgeIntervals& e) {
    return fixed_intervals_on(result.layout, e.a, e.b, e.intervals, tolerance);
  }, [&](const IntervalOptions& o) { return assign_intervals(result.layout, o); });
  result.interval_seconds = since(start);

  start = std::chrono::steady_clock::now();
  const std::vector<TopoDS_Face> block_faces = replay_cuts_occt(face_to_replay(face), face.grid, d.cuts, options.episode);
  if (block_faces.size() != d.blocks.size()) throw std::logic_error("mesh: the replay gave a different number of blocks");
  for (size_t b = 0; b < d.blocks.size(); ++b) {
    const Box got = vertex_box(block_faces[b]), want = d.blocks[b];
    const double tol = std::max(face.planar.tolerance, 1e-7 * face.grid.size);
    if (std::fabs(got.xmin - want.xmin) > tol || std::fabs(got.xmax - want.xmax) > tol ||
        std::fabs(got.ymin - want.ymin) > tol || std::fabs(got.ymax - want.ymax) > tol) {
      throw std::logic_error("mesh: replayed block " + std::to_string(b + 1) + " is not the decomposition's");
    }
  }
  result.model = conformal_merge(block_faces);
  result.merge_seconds = since(start);

  start = std::chrono::steady_clock::now();
  result.mesh = mapped_mesh(result.model, d.blocks, face.grid, result.layout, result.intervals, face.planar.z,
                            face.planar.tolerance);
  result.mesh_seconds = since(start);

  start = std::chrono::steady_clock::now();
  result.quality = mesh_quality(result.mesh);
  result.conformity = check_conformity(result.mesh, face.planar.polygon);
  result.check_seconds = since(start);
  return result;
}

ConformalBlocks region_occt_model(const InputFace& face, const RegionDecomposition& d, const MeshOptions& options) {
  // OpenCASCADE stays the judge: it cuts the face as the engine did, and merges the parts.
  const auto lock = lock_general_engine();
  const std::vector<TopoDS_Face> parts = replay_region_cuts_occt(face.occt, face.region, d, options.general, &face.arcs);
  if (parts.size() != d.finished.size()) throw std::logic_error("mesh: the replay gave a different number of parts");
  return conformal_merge(parts, face.region.quantum());
}

namespace {

constexpr double kAcuteTip = 60.0 * M_PI / 180.0;      // a convex corner sharper than this is a tip
constexpr double kTipShare = 0.97;                      // the tip quad's sine, at least this share of the corner's
constexpr double kLeastTipStep = 0.5 * M_PI / 180.0;   // the finest turn asked of an edge from a tip
constexpr double kTipGradingRatios[] = {1.25, 1.4};     // the gradings from a tip tried (graded_fractions)
constexpr double kGradedTipShare = 0.99;                // kTipShare of edges graded from the tip (a few quads more)

// The interval counts a block model's edges along arcs take at least: one per chord step of the arc
// (chord), finer on an edge from an acute tip (acute_tip_steps); one per kMeshEdgeArcSteps of them on a convex arc (relaxed); the chord steps as targets
// (target; 0 off arcs); relaxable when some relaxed count is below its chord count.
struct ArcMinima {
  std::vector<int> chord, relaxed;
  std::vector<double> target;
  bool relaxable = false;
  std::vector<int> tips;  // chord, finer on the edges from acute tips (acute_tip_steps)
  bool tipped = false;    // some edge's is finer
};
// Per arc of the face, the largest turn (radians) of a mesh edge along it from its first and its last
// end (0: no limit). An end at a convex corner sharper than kAcuteTip (boundary_corners, the arcs'
// tangents taken there) is a tip: the quad there has the angle of the chords to the first nodes, not
// the tangents', smaller by half of each first edge's turn. The turns keep the quad's sine within
// share (kTipShare, kGradedTipShare) of the corner's, shared between the corner's arcs (a
// crescent's tip: both sides are arcs).
// Inputs: loops, arcs, the face's. Output: the limits, one pair per arc of arcs.
std::vector<std::array<double, 2>> acute_tip_steps(const std::vector<Ring>& loops, const FaceArcs& arcs, double share) {
  std::vector<std::array<double, 2>> tip(arcs.arcs.size(), {0.0, 0.0});
  for (const BoundaryCorner& corner : boundary_corners(loops, arcs)) {
    if (corner.angle >= kAcuteTip) continue;
    const int on_arcs = (corner.arc_in >= 0) + (corner.arc_out >= 0);
    if (on_arcs == 0) continue;
    const double deficit = corner.angle - std::asin(share * std::sin(corner.angle));
    const double limit = std::max(kLeastTipStep, 2.0 * deficit / on_arcs);
    for (const int a : {corner.arc_in, corner.arc_out}) {
      if (a < 0) continue;
      const CircularArc& arc = arcs.arcs[static_cast<size_t>(a)];
      if (std::fabs(arc.sweep) >= 2.0 * M_PI - 1e-9) continue;  // a full circle has no end
      const Point2 first = arc.first(), last = arc.last();
      const bool at_first = std::hypot(first.x - corner.at.x, first.y - corner.at.y) <=
                            std::hypot(last.x - corner.at.x, last.y - corner.at.y);
      double& step = tip[static_cast<size_t>(a)][at_first ? 0 : 1];
      step = step > 0.0 ? std::min(step, limit) : limit;
    }
  }
  return tip;
}

// Inputs: model's edge along an arc of arcs; steps, per arc of arcs (acute_tip_steps). Output: the
//         limits at the edge's ends a and b where they are ends of its arc (0: none).
std::array<double, 2> edge_tip_limits(const BlockModel& model, const ModelEdge& edge, const FaceArcs& arcs,
                                      const std::vector<std::array<double, 2>>& steps) {
  const CircularArc& arc = arcs.arcs[static_cast<size_t>(edge.arc)];
  std::array<double, 2> limits{0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    const int end = arc.end_at(model.vertices[static_cast<size_t>(k == 0 ? edge.a : edge.b)], arcs.tolerance);
    if (end >= 0) limits[static_cast<size_t>(k)] = steps[static_cast<size_t>(edge.arc)][static_cast<size_t>(end)];
  }
  return limits;
}

// Inputs: model, its edges on arcs; arcs, the face's; tip, acute_tip_steps of the face.
ArcMinima arc_minima(const BlockModel& model, const FaceArcs& arcs, const std::vector<std::array<double, 2>>& tip) {
  const size_t n_edges = model.edges.size();
  ArcMinima m{std::vector<int>(n_edges, 0), std::vector<int>(n_edges, 0), std::vector<double>(n_edges, 0.0), false,
              std::vector<int>(n_edges, 0), false};
  for (size_t e = 0; e < n_edges; ++e) {
    const ModelEdge& edge = model.edges[e];
    if (edge.arc < 0) continue;
    const CircularArc& arc = arcs.arcs[static_cast<size_t>(edge.arc)];
    const double step = std::fabs(arc.sweep) / arc_chord_count(arc);
    // The intervals that keep every one within `steps` chord steps of the arc.
    auto intervals = [&](int steps) { return std::max(1, static_cast<int>(std::ceil(std::fabs(edge.arc_sweep) / (steps * step) - 1e-6))); };
    m.chord[e] = intervals(1);
    m.target[e] = m.chord[e];
    m.relaxed[e] = intervals(arc.outside ? 1 : kMeshEdgeArcSteps);
    m.relaxable = m.relaxable || m.relaxed[e] < m.chord[e];
    m.tips[e] = m.chord[e];
    // An edge from an acute tip: its intervals as fine as the tip wants.
    for (const double limit : edge_tip_limits(model, edge, arcs, tip)) {
      if (!(limit > 0.0)) continue;
      const int fine = static_cast<int>(std::ceil(std::fabs(edge.arc_sweep) / limit - 1e-6));
      m.tipped = m.tipped || fine > m.tips[e];
      m.tips[e] = std::max(m.tips[e], fine);
    }
  }
  return m;
}

// The intervals of model's arc edges with their nodes graded from acute tips (graded_fractions at
// grading's ratio): per edge from a tip, the fewest from its chord count up (chord) whose first
// intervals keep within the tip's limits. Others: their chord count. *graded: some edge's first
// interval is shorter than its uniform one.
std::vector<int> graded_counts(const BlockModel& model, const FaceArcs& arcs, const ArcEndGrading& grading,
                               const std::vector<int>& chord, bool* graded) {
  std::vector<int> counts = chord;
  *graded = false;
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& edge = model.edges[e];
    if (edge.arc < 0) continue;
    const auto [fa, fb] = edge_tip_limits(model, edge, arcs, grading.steps);
    const double sweep = std::fabs(edge.arc_sweep);
    const double finest = std::min(fa > 0.0 ? fa : 1e300, fb > 0.0 ? fb : 1e300);
    if (!(finest < sweep / chord[e])) continue;  // no tip, or the uniform intervals are fine enough
    *graded = true;
    // At most the uniform count that keeps every interval within the finest limit.
    const int most = std::max(chord[e], static_cast<int>(std::ceil(sweep / finest - 1e-6)));
    for (int n = chord[e]; n <= most; ++n) {
      counts[e] = n;
      const std::vector<double> f = graded_fractions(n, sweep, fa, fb, grading.ratio);
      const bool a_fine = !(fa > 0.0) || f[1] * sweep <= fa * (1.0 + 1e-9);
      const bool b_fine = !(fb > 0.0) || (1.0 - f[f.size() - 2]) * sweep <= fb * (1.0 + 1e-9);
      if (a_fine && b_fine) break;
    }
  }
  return counts;
}

// mesh_region_decomposition with the block model's tolerance (and the conformity check's) at
// tolerance_quanta quanta. With remake_failed false, a first mesh that fails its check is returned
// as it is (the model as the templates place its feet is not tried).
MeshResult mesh_region_decomposition_at(const InputFace& face, const RegionDecomposition& d, const MeshOptions& options,
                                        double tolerance_quanta, bool remake_failed) {
  if (!face.is_general()) throw std::logic_error("mesh_region_decomposition: the face is rectilinear");
  if (!d.complete()) {
    const size_t left = d.unfinished.size();
    throw InputError("the decomposition is incomplete (" + counted(static_cast<long long>(left), "part") + " left after " +
                     counted(static_cast<long long>(d.cuts.size()), "cut") + "); meshing needs blocks only: raise --max-steps or use another policy");
  }
  MeshResult result;
  const double h = checked_target_size(face, options, result);
  const double q = face.region.quantum();
  const double tolerance = general_mesh_tolerance(face, tolerance_quanta);
  const std::vector<Ring> loops = face.region.loops();
  result.bound = scaled_jacobian_bound(loops, face.arcs);
  result.topology_bound = topology_jacobian_bound(loops, face.arcs);

  // Intervals first: an infeasible request fails before the slower CAD work.
  auto start = std::chrono::steady_clock::now();
  // The block model with templates' feet a hair apart made one (block_model's FeetSnap::near). Where
  // its blocks admit no counts, the model as the templates place them: round a ring of parts, hair-thin
  // edges between two templates' feet can be what cannot balance (all of them), or what lets the
  // counts balance (those left where others were made one). Where both mesh, the better mesh is kept
  // (below). Where neither does, the model with feet a fair way apart made one too (FeetSnap::far): a
  // hole's cell cut into quarters through the hole, each quarter a template, puts its feet on the
  // cuts a twentieth of a side apart, and round the hole those edges cannot balance.
  result.block_model = block_model(d, d.rules, q, false, FeetSnap::near, tolerance_quanta, face.straight_vertices);
  merge_arc_chains(result.block_model, face.arcs);
  // An edge along an arc gets at least one interval per chord step of the arc: a quad's edge along the
  // arc is a chord the conformity check finds on the arc (FaceArcs::arc_of_mesh_edge). That minimum can
  // make a block side holding a tight convex arc (a rounded acute tip) carry far more intervals than
  // its length asks for, and its quads fan into the tip from the shorter side opposite. So a poor mesh
  // (below kArcTargetsBelow of the topology bound) with a convex arc is made a second time with the
  // chord steps as the program's targets instead (IntervalOptions::edge_target), a convex arc's edge
  // turning by up to kMeshEdgeArcSteps chord steps, a hole's or a concave fillet's one as before; the
  // better mesh is kept (MeshResult::arc_targets).
  const std::vector<std::array<double, 2>> tip_steps = acute_tip_steps(loops, face.arcs, kTipShare);
  ArcMinima minima = arc_minima(result.block_model, face.arcs, tip_steps);
  const BlockModel& model = result.block_model;
  auto snapped_model = [&](FeetSnap snap) {
    BlockModel m = block_model(d, d.rules, q, false, snap, tolerance_quanta, face.straight_vertices);
    merge_arc_chains(m, face.arcs);
    return m;
  };
  // (model is result's block model: how its feet are made one is its feet and snapped_feet, whichever
  // model is kept below.)
  try {
    assign_arc_intervals(result, model, options, h, tolerance, minima.chord, {});
  } catch (const NoIntervalAssignment&) {
    bool assigned = false;
    if (model.snapped_feet > 0) {
      result.block_model = snapped_model(FeetSnap::placed);
      minima = arc_minima(result.block_model, face.arcs, tip_steps);
      try {
        assign_arc_intervals(result, model, options, h, tolerance, minima.chord, {});
        assigned = true;
      } catch (const NoIntervalAssignment&) {
        // the far model below
      }
    }
    if (!assigned) {
      BlockModel far = snapped_model(FeetSnap::far);
      if (far.snapped_feet == 0) throw;  // the model as placed, which admits none
      result.block_model = std::move(far);
      minima = arc_minima(result.block_model, face.arcs, tip_steps);
      assign_arc_intervals(result, model, options, h, tolerance, minima.chord, {});
    }
  }
  result.interval_seconds = since(start);

  start = std::chrono::steady_clock::now();
  if (options.occt_model) result.model = region_occt_model(face, d, options);
  result.merge_seconds = since(start);

  start = std::chrono::steady_clock::now();
  mesh_blocks(result, model, face, d, options, h, tolerance, minima.chord, {});
  result.mesh_seconds = since(start);

  start = std::chrono::steady_clock::now();
  result.quality = mesh_quality(result.mesh);
  result.conformity = check_conformity(result.mesh, loops, tolerance, face.arcs);
  result.check_seconds = since(start);
  if (!remake_failed && !result.conformity.conformal) return result;
  auto poor = [&] {
    return result.conformity.conformal && judged_jacobian(result.quality) < kArcTargetsBelow * result.topology_bound;
  };
  // Keeps again's mesh (and, with own_model, its block model) when it is better (judged_jacobian: a
  // degenerate quad ranks a mesh below any without) and conformal.
  auto keep_if_better = [&](MeshResult& again, bool own_model) {
    const MeshQuality quality = mesh_quality(again.mesh);
    if (result.conformity.conformal && !(judged_jacobian(quality) > judged_jacobian(result.quality))) return false;
    Conformity conformity = check_conformity(again.mesh, loops, tolerance, face.arcs);
    if (!conformity.conformal) return false;
    if (own_model) result.block_model = std::move(again.block_model);
    result.fixed = std::move(again.fixed);
    result.intervals = std::move(again.intervals);
    result.mesh = std::move(again.mesh);
    result.smoothing = again.smoothing;
    result.quality = quality;
    result.conformity = std::move(conformity);
    return true;
  };
  // A second mesh of `on` (result's block model, or again's own) with these minima and targets, kept
  // when better. Its failure (the fixed counts or the quad limit forbid it: InputError; or GLPK found
  // no counts in its quick limit) leaves the first mesh standing; a logic error, a bug, is not
  // swallowed.
  auto remake = [&](MeshResult& again, const BlockModel& on, const std::vector<int>& minimum,
                    const std::vector<double>& target, bool own_model, const ArcEndGrading* graded = nullptr) {
    start = std::chrono::steady_clock::now();
    bool kept = false;
    try {
      assign_arc_intervals(again, on, options, h, tolerance, minimum, target, true);
      mesh_blocks(again, on, face, d, options, h, tolerance, minimum, target, true, graded);
      kept = keep_if_better(again, own_model);
    } catch (const std::runtime_error&) {
      // the first mesh stands
    }
    result.mesh_seconds += since(start);
    return kept;
  };
  if (model.feet == FeetSnap::near && model.snapped_feet > 0) {
    // Feet made one move pieces and take edges from the program: the model as the templates place
    // them can mesh better (60 unseen flanges, the feet made one always: 15 rose, and 8 fell by
    // 0.006-0.12). (The far model is made only where the model as placed admits no counts.)
    MeshResult again;
    again.block_model = snapped_model(FeetSnap::placed);
    const ArcMinima again_minima = arc_minima(again.block_model, face.arcs, tip_steps);
    if (remake(again, again.block_model, again_minima.chord, {}, true)) minima = again_minima;
  }
  if (options.arc_targets && minima.relaxable && poor()) {
    MeshResult again;  // its intervals, mesh and smoothing (of result's block model)
    result.arc_targets = remake(again, model, minima.relaxed, minima.target, false);
  }
  // A poor mesh with a template part that the two-corner template would finish better (block.h,
  // two_corner_improves) is made again with that template there (its own block model, the chord
  // steps as minima); the better mesh is kept (MeshResult::two_corner).
  if (options.two_corner && poor() &&
      std::any_of(d.finished.begin(), d.finished.end(), [&](const FinishedRegion& f) {
        return f.is_template && two_corner_improves(f.region, d.rules);
      })) {
    MeshResult again;
    again.block_model = block_model(d, d.rules, q, true, model.snapped_feet > 0 ? model.feet : FeetSnap::placed, tolerance_quanta,
                                     face.straight_vertices);
    merge_arc_chains(again.block_model, face.arcs);
    const ArcMinima again_minima = arc_minima(again.block_model, face.arcs, tip_steps);
    if (remake(again, again.block_model, again_minima.chord, {}, true)) {
      result.two_corner = true;
      result.arc_targets = false;
    }
  }
  // A convex corner sharper than kAcuteTip where an arc ends: the quad there has the angle of the
  // chord from the corner to the arc's first node, not the tangent's. A mesh short of
  // kGradedTipShare of the face's bound is made again with the arc's edges from such tips graded
  // from them (their first intervals within what acute_tip_steps asks for kGradedTipShare, then for
  // kTipShare, growing by each of kTipGradingRatios: a few more quads), until one reaches
  // kGradedTipShare; one still short of kTipShare, with those edges fine enough for kTipShare all
  // along (many more quads). The best mesh is kept
  // (MeshResult::acute_tips). Which of them meshes a face best depends on its blocks: a crescent's
  // row of quads along its tighter arc skews where a uniformly fine side meets coarse ones, and at
  // one grading and not at another.
  // (The block model kept: the two-corner template's is another, with other edges.)
  const ArcMinima kept = result.two_corner ? arc_minima(result.block_model, face.arcs, tip_steps) : minima;
  for (const double share : {kGradedTipShare, kTipShare}) {
    if (!result.conformity.conformal || judged_jacobian(result.quality) >= kGradedTipShare * result.bound) break;
    const std::vector<std::array<double, 2>> graded_steps = share == kTipShare ? tip_steps : acute_tip_steps(loops, face.arcs, share);
    for (const double ratio : kTipGradingRatios) {
      if (judged_jacobian(result.quality) >= kGradedTipShare * result.bound) break;
      const ArcEndGrading grading{graded_steps, ratio};
      bool graded = false;
      const std::vector<int> counts = graded_counts(result.block_model, face.arcs, grading, kept.chord, &graded);
      if (!graded) break;
      MeshResult again;
      if (remake(again, result.block_model, counts, {}, false, &grading)) {
        result.acute_tips = true;
        result.arc_targets = false;
      }
    }
  }
  if (kept.tipped && result.conformity.conformal && judged_jacobian(result.quality) < kTipShare * result.bound) {
    MeshResult again;
    if (remake(again, result.block_model, kept.tips, {}, false)) {
      result.acute_tips = true;
      result.arc_targets = false;
    }
  }
  return result;
}

}  // namespace

double general_mesh_tolerance(const InputFace& face, double tolerance_quanta) {
  return std::max({face.planar.tolerance, tolerance_quanta * face.region.quantum(), 1e-9 * face.region.bbox().longer_side()});
}

MeshResult mesh_region_decomposition(const InputFace& face, const RegionDecomposition& d, const MeshOptions& options) {
  MeshResult result = mesh_region_decomposition_at(face, d, options, kModelToleranceQuanta, false);
  if (result.conformity.conformal) return result;
  // A T-junction the model missed leaves hanging nodes: the model made again with the wider tolerance
  // (kWideModelToleranceQuanta), kept when its mesh passes the check. Where it does not, the first
  // model's other meshes (the feet as the templates place them), as without the wider one; their
  // failure leaves the first mesh. (The wider model first: where it is needed, the first model's
  // other meshes fail their check too, and each is a whole interval program and mesh.)
  try {
    MeshResult wide = mesh_region_decomposition_at(face, d, options, kWideModelToleranceQuanta, true);
    if (wide.conformity.conformal) {
      wide.wide_tolerance = true;
      return wide;
    }
  } catch (const std::runtime_error&) {
    // the first model's other meshes below
  }
  return mesh_region_decomposition_at(face, d, options, kModelToleranceQuanta, true);
}

}  // namespace autoblock
