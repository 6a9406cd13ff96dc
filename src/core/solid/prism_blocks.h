// The hexahedral blocks of a swept solid as OpenCASCADE solids: the cap's conformal blocks (faces
// sharing their edges, conformal_merge.h) swept along the sweep vector. The sweep of a shared edge is
// one face, so neighbouring prisms share their faces, edges and vertices, T-junctions included: a
// conformal partition of the solid.
#pragma once

#include <vector>

#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Vec.hxx>

#include "core/geometry/placement.h"
#include "core/mesh/conformal_merge.h"

namespace autoblock {

struct PrismBlocks {
  TopoDS_Compound compound;          // the solids below, nothing else
  std::vector<TopoDS_Solid> solids;  // one per block of the cap, same order
};

// Inputs:  blocks, the cap's merged blocks in the cap's frame; frame, where that frame lies in the
//          model; sweep, model coordinates.
// Outputs: the prisms in the model's coordinates. Throws std::runtime_error when OpenCASCADE fails or
//          a block does not give exactly one solid.
PrismBlocks prism_blocks(const ConformalBlocks& blocks, const Placement& frame, const gp_Vec& sweep);

}  // namespace autoblock
