// Replay a decomposition's cuts on the real OpenCASCADE face (BRepAlgoAPI_Splitter, see
// occt_split.h), checking at every cut that OpenCASCADE and the grid engine agree.
#pragma once

#include <vector>

#include <TopoDS_Face.hxx>

#include "core/env/episode.h"
#include "core/geometry/grid_face.h"

namespace autoblock {

// Inputs:  face, the input face as OpenCASCADE holds it; grid, the same face on its grid;
//          cuts, a decomposition's cut sequence (Episode::cuts()).
// Outputs: the faces of the blocks, in the order the episode set them aside, cut from the input
//          face by OpenCASCADE; then, if the episode was truncated, the parts left unfinished.
// Throws std::logic_error when OpenCASCADE's pieces differ from the grid engine's (number of
// pieces, areas or corner counts) and std::runtime_error when OpenCASCADE fails.
std::vector<TopoDS_Face> replay_cuts_occt(const TopoDS_Face& face, const GridFace& grid,
                                          const std::vector<CutRecord>& cuts, EpisodeOptions options = {});

}  // namespace autoblock
