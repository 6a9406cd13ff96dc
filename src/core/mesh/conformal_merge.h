// Conformal merge: the blocks put back together as one partitioned face model.
//
// OpenCASCADE's general fuse (BRepAlgoAPI_BuilderAlgo) on the block faces makes coincident edges
// one shared edge and imprints every T-junction (a vertex on a neighbour's side splits that side),
// so neighbouring blocks share their edges and vertices (IsSame). The union of the blocks is the
// face they were cut from, holes included.
#pragma once

#include <vector>

#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>

namespace autoblock {

struct ConformalBlocks {
  TopoDS_Compound compound;         // the faces below, nothing else
  std::vector<TopoDS_Face> faces;   // one per input block, same order
};

// Inputs:  blocks, planar faces in one plane that do not overlap (e.g. replay_cuts_occt's); fuzzy,
//          OpenCASCADE's fuzzy value (0: exact; a general face's blocks, whose cut ends were rounded
//          to the face's lattice, use its quantum).
// Outputs: the merged model. Each face has the same area as its block (within 1e-9 relative, plus
//          fuzzy times its perimeter).
// Throws std::runtime_error when OpenCASCADE fails, a block does not come back as exactly one
// face, or the result fails BRepCheck_Analyzer.
ConformalBlocks conformal_merge(const std::vector<TopoDS_Face>& blocks, double fuzzy = 0.0);

}  // namespace autoblock
