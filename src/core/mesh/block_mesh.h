// Mapped meshing of a general block model (block_model.h): nodes on every model edge once, then
// every block by transfinite interpolation from its four logical sides (transfinite.h).
//
// An edge with n intervals gets n - 1 nodes evenly spaced between its vertices, made once and used
// by both pieces it bounds, so neighbours share their nodes (no hanging nodes). A block's side is the
// chain of its edges' nodes from one corner to the next; opposite sides carry equal counts
// (edge_intervals.h), and the block's interior nodes are the Coons patch of its four sides.
#pragma once

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
QuadMesh block_model_mesh(const BlockModel& model, const std::vector<int>& intervals, double z,
                          const FaceArcs* arcs = nullptr, const std::vector<char>* by_length = nullptr);

}  // namespace autoblock
