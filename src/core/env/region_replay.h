// Replay a general decomposition's cuts on the real OpenCASCADE face (BRepAlgoAPI_Splitter with the
// cut's chords as tools, see occt_split.h), checking at every cut that OpenCASCADE and the general
// engine (core/region) agree: OpenCASCADE stays the judge, as replay_cuts_occt is for the grid engine.
#pragma once

#include <vector>

#include <TopoDS_Face.hxx>

#include "core/geometry/circular_arc.h"
#include "core/region/region_policy.h"

namespace autoblock {

// Inputs:  face, the input face in its frame (InputFace::occt); region, the same face on its lattice
//          (InputFace::region); decomposition, made of region with options (the same reward preset
//          and block rules).
// Outputs: the faces of the finished parts (blocks and templates) in the order set aside, cut from
//          the input face by OpenCASCADE; then the parts left unfinished, if any.
//          arcs, the face's circular edges (InputFace::arcs; nullptr: none): a chord's end on an arc's
//          polygon is moved along the chord onto the arc, so that the cut reaches the true boundary.
// Throws std::logic_error when OpenCASCADE's pieces differ from the engine's (number of pieces, or an
// area beyond what the lattice's rounding and the arcs' segments explain) and std::runtime_error
// when OpenCASCADE fails.
std::vector<TopoDS_Face> replay_region_cuts_occt(const TopoDS_Face& face, const Region& region,
                                                 const RegionDecomposition& decomposition,
                                                 RegionEpisodeOptions options = {}, const FaceArcs* arcs = nullptr);

}  // namespace autoblock
