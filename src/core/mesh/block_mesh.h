// Mapped meshing of a general block model (block_model.h): nodes on every model edge once, then
// every block by transfinite interpolation from its four logical sides (transfinite.h).
//
// An edge with n intervals gets n - 1 nodes evenly spaced between its vertices, made once and used
// by both pieces it bounds, so neighbours share their nodes (no hanging nodes). A block's side is the
// chain of its edges' nodes from one corner to the next; opposite sides carry equal counts
// (edge_intervals.h), and the block's interior nodes are the Coons patch of its four sides.
#pragma once

#include <array>
#include <vector>

#include "core/geometry/circular_arc.h"
#include "core/mesh/block_model.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock {

// A face with circular arcs (circular_arc.h): the model's boundary edges (used by one block) that are
// chords of an arc get their nodes on the arc, evenly spaced in angle, and the boundary vertices on
// an arc's polygon move onto the arc; the blocks' interiors follow by transfinite interpolation.
//
// Inputs:  model; intervals, per model edge (equal totals on opposite sides of every block); z, the
//          face's plane; arcs, the face's (nullptr or empty: straight edges only).
// Outputs: the quad mesh, quads block by block (the model's blocks; quad_block holds the block's
//          part, so a template's quads carry its part), each block's quads row by row,
//          counter-clockwise. mesh.blocks is the number of parts.
// Throws std::logic_error when a block's opposite sides carry different counts.
//          by_length (nullptr: none), per model block: fill it with transfinite_grid_by_length.
//          grading (nullptr: none): an edge of an arc from an end with a limit spaces its nodes by
//          graded_fractions (an acute tip's quad, mesh_pipeline.cpp).
constexpr double kGradingRatio = 1.25;
struct ArcEndGrading {
  // Per arc of the face, the largest turn (radians, 0: no limit) of the first interval from its
  // first and from its last end.
  std::vector<std::array<double, 2>> steps;
  double ratio = kGradingRatio;  // each interval over the one before it, from such an end
};
QuadMesh block_model_mesh(const BlockModel& model, const std::vector<int>& intervals, double z,
                          const FaceArcs* arcs = nullptr, const std::vector<char>* by_length = nullptr,
                          const ArcEndGrading* grading = nullptr);

// Node spacing graded from an edge's ends: intervals growing by ratio from a first one at most
// first_a (from the start) or first_b (from the end) long, up to a common size that makes them add
// up; uniform where neither limit is below the uniform interval. Where the grading cannot fill the
// edge at that ratio, the first intervals are as short as it allows (all scaled alike).
// Inputs:  n >= 1 intervals; total > 0, the edge's length (or turn); first_a, first_b (<= 0: none);
//          ratio > 1.
// Outputs: n + 1 fractions of the total, from 0 to 1, increasing.
std::vector<double> graded_fractions(int n, double total, double first_a, double first_b, double ratio = kGradingRatio);

}  // namespace autoblock
