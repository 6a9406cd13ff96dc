// Smoothing of a quad mesh that keeps its boundary and never lowers the minimum scaled Jacobian.
//
// A sweep visits every node that is not on the mesh's boundary (boundary nodes are the ends of edges
// used by one quad: the face's outer loop and holes). For each it tries two positions: the
// isoparametric one, the mean over its quads of (previous + next - opposite corner), which keeps an
// affine (parallelogram) grid exactly where it is, and the Laplacian one, the mean of its edge
// neighbours; and halfway to each. The node moves to the candidate whose worst quad around it (the
// smallest scaled Jacobian, mesh_quality.h) is best, only if that is better than where it is. A move
// changes only the quads around the node, and only for the better at their worst, so the mesh's
// minimum scaled Jacobian never drops and no quad inverts. Sweeps stop after max_sweeps, or when a
// sweep improves no node's worst quad by more than 1e-6. Then, worst first, up to worst_rounds
// rounds (stopping at the first that moves nothing): the
// free corners of the quads within 0.05 of the minimum (at most 400, worst first) each move by a
// pattern search (eight directions, a quarter of the node's mean edge length, halved up to six
// times), under the same rule: a move only when the node's worst quad gets better. In those rounds a
// boundary node *slides* along the boundary (two directions) where all its quads are one block's
// (not where a block's side meets the boundary) and it lies in line with its two boundary neighbours
// (a straight stretch: not a corner) or on a circle of the face's arcs with both, staying on that line
// or circle within [0.05, 0.95] of the way between them: a block whose opposite sides differ in
// length gets its boundary spacing evened where its quads are worst. No other boundary node moves
// (an arc's ends, its joins with straight edges, the pinned vertices between edges in line, stay).
//
// Every move also keeps each quad around the node within kSmoothingEdgeRatio of longest edge over
// shortest, or within its ratio before the move where that was more: the scaled Jacobian alone is
// served well by drawing two nodes together, so that a quad becomes a triangle with an edge of no
// length (or a sliver) whose corners still measure well. Smoothed so, 116 of 200 generated faces with
// arcs had a quad whose edge ratio passed 100 (one 10^8), where gmsh's largest on each face was below
// 16 (BENCHMARKS.md, "Smoothing that draws no quad into a triangle").
#pragma once

#include <vector>

#include "core/geometry/circular_arc.h"
#include "core/geometry/point.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock {

struct SmoothingReport {
  int sweeps = 0;         // sweeps run
  int moves = 0;          // node moves made
  double min_before = 0.0, min_after = 0.0;  // the mesh's minimum scaled Jacobian
};

// Inputs:  mesh, counter-clockwise quads; max_sweeps >= 0 (0: nothing moves); worst_rounds >= 0,
//          the worst-first rounds after the sweeps; arcs, the face's circular edges in the mesh's
//          frame (nullptr: none; their nodes stay); pinned, points of the boundary whose nodes never
//          slide though in line with their neighbours (the face's vertices between two edges in line,
//          InputFace::straight_vertices: each is a node of the mesh, and stays one).
// Outputs: mesh with its interior nodes, and the boundary nodes that slide, moved as above; the report.
constexpr int kWorstRounds = 40;
constexpr double kSmoothingEdgeRatio = 16.0;
SmoothingReport smooth_quad_mesh(QuadMesh& mesh, int max_sweeps, int worst_rounds = kWorstRounds,
                                 const FaceArcs* arcs = nullptr, const std::vector<Point2>& pinned = {});

// A smoothed mesh may keep an inverted quad where its sweeps stopped at their limit (a sliver between
// a cut and a hole's arc, one element across): each sweep lifts the worst quads a little. The quads
// within `rings` rings of the inverted ones (quads sharing a node, ring by ring) are smoothed on their
// own, up to max_sweeps sweeps and no worst-first rounds (they slide boundary nodes, and this patch's
// boundary is not the face's). Only nodes whose quads all lie in the patch move, under the smoothing's
// rule: no other quad changes, the face's boundary nodes stay, and no quad's worst gets worse.
// Inputs:  mesh, counter-clockwise quads; rings >= 0; max_sweeps >= 0.
// Outputs: mesh with those nodes moved (unchanged without inverted quads); the inverted quads left.
int untangle_quad_mesh(QuadMesh& mesh, int rings, int max_sweeps);

}  // namespace autoblock
