// The grid engine as the fast path of general faces: a face whose edges all run along two
// perpendicular directions (rectilinear in its own frame, however it is turned) is decomposed by the
// exact grid engine in that frame, and its blocks are turned back. Such a face turned by any angle
// gets exactly the blocks of its axis-aligned twin, turned.
#pragma once

#include <optional>
#include <vector>

#include "core/env/decomposition.h"
#include "core/geometry/rectilinear_polygon.h"
#include "core/region/region.h"

namespace autoblock {

// A rotation about a centre: frame coordinates = R(-angle) (global - centre).
struct FaceFrame {
  double angle = 0.0;  // radians, [0, pi / 2)
  Point2 centre;
  Point2 to_frame(Point2 p) const;
  Point2 to_global(Point2 p) const;
};

// Inputs:  face (a region, not empty).
// Outputs: the frame in which every edge of the face runs along X or Y (within twice the face's
//          quantum at its ends), centred on the face's first vertex; nothing when the face is not rectilinear in
//          any frame. An axis-aligned face gets angle 0.
std::optional<FaceFrame> rectilinear_frame(const Region& face);

// Inputs:  face; frame, from rectilinear_frame(face).
// Outputs: the face in its frame as a validated rectilinear polygon (validate_polygon.h).
RectilinearPolygon polygon_in_frame(const Region& face, const FaceFrame& frame);

// Inputs:  face; frame; policy, a grid-engine policy; options.
// Outputs: the grid decomposition of the face in its frame (blocks as boxes in frame coordinates),
//          and in *blocks the same blocks turned back, as regions on the face's lattice.
Decomposition decompose_in_frame(const Region& face, const FaceFrame& frame, Policy& policy, EpisodeOptions options,
                                 std::vector<Region>* blocks);

}  // namespace autoblock
