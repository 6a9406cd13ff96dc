// Mapped meshing of a conformal block model: nodes on every shared edge once, then every block by
// transfinite interpolation from its four logical sides (transfinite.h).
//
// Every edge of the merged model (conformal_merge.h) is discretised once, so the blocks on both
// sides of a shared edge use the same nodes: no hanging nodes. An edge's nodes are those of the
// strips that divide it (strip_layout.h) with their assigned counts (interval_assignment.h). A
// block's four logical sides are the chains of its edges between its corners (a side may hold
// several edges after imprinting).
#pragma once

#include <vector>

#include "core/geometry/grid_face.h"
#include "core/mesh/conformal_merge.h"
#include "core/mesh/interval_assignment.h"
#include "core/mesh/quad_mesh.h"
#include "core/mesh/strip_layout.h"

namespace autoblock {

// Inputs:  model, the merged blocks (faces in block order); blocks, the same as boxes; face, the
//          input face on its grid (for its size); layout, strip_layout(face, blocks); intervals, counts per strip;
//          z, the face's plane; tolerance, how far a model vertex may be from its grid point (the
//          face's tolerance, as validated; at least 1e-9 of the face's size). Nodes sit on the grid.
// Outputs: the quad mesh, quads block by block, each block's quads row by row.
// Throws std::logic_error when the model does not match the blocks or the grid (a face with a
//        hole, an edge that is not on a block side, opposite sides with different node counts).
QuadMesh mapped_mesh(const ConformalBlocks& model, const std::vector<Box>& blocks, const GridFace& face,
                     const StripLayout& layout, const IntervalAssignment& intervals, double z,
                     double tolerance = 0.0);

}  // namespace autoblock
