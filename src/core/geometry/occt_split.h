// Split an OpenCASCADE face along a full axis-parallel line (BRepAlgoAPI_Splitter), then merge
// collinear edges (ShapeUpgrade_UnifySameDomain) so that vertex counts are true.
//
// The decomposition environment cuts exact grid parts (axis_cut.h) because a search makes millions
// of cuts; this is the same cut on real CAD faces. Tests check that both agree on every cut of
// hundreds of episodes, and decomposition results are replayed through it (replay_cuts.h).
#pragma once

#include <utility>
#include <vector>

#include <TopoDS_Face.hxx>

#include "core/geometry/axis_cut.h"

namespace autoblock {

// Inputs:  face (planar, parallel to XY); direction; coordinate, the line's y (horizontal) or
//          x (vertical).
// Outputs: the faces the line splits the face into, collinear edges merged; the face itself (N = 1)
//          when the line misses the face's interior.
// Throws std::runtime_error when OpenCASCADE fails.
std::vector<TopoDS_Face> split_face_along_line(const TopoDS_Face& face, CutDirection direction, double coordinate);

// Inputs:  face (planar, parallel to XY); segments, each from a to b in the face's plane, ending on
//          the face's boundary (or on each other) within fuzzy; fuzzy >= 0, OpenCASCADE's fuzzy value
//          (gaps up to it count as touching).
// Outputs: the faces the segments split the face into, collinear edges merged.
// Throws std::runtime_error when OpenCASCADE fails.
std::vector<TopoDS_Face> split_face_along_segments(const TopoDS_Face& face,
                                                   const std::vector<std::pair<Point2, Point2>>& segments,
                                                   double fuzzy);

}  // namespace autoblock
