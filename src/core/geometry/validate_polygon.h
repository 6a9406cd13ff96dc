// Turn the boundary loops read from a file into a valid RectilinearPolygon, or say exactly what is
// wrong and where.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

// One boundary loop as read from a file: its vertices in order (implicitly closed) and a name for
// messages such as "outer wire" or "wire 2".
struct RawRing {
  std::string name;
  std::vector<Point2> points;
};

// Inputs:  values; tol. Output: each value mapped to the mean of its cluster (sorted values closer
//          than tol to a neighbour share one cluster).
std::map<double, double> snap_map(std::vector<double> values, double tol);

// Inputs:  rings, the face's wires as read.
// Outputs: the face's tolerance (tolerance.h), from the bounding box of all its vertices.
// Throws InputError when: there is no wire; a wire has fewer than three vertices; a coordinate is not
// finite or beyond kMaximumCoordinate; the face is too small or its bounding box has zero or tiny
// width or height. Both validators (this one and region/validate_region.h) start here.
double face_tolerance(const std::vector<RawRing>& rings);

// Inputs:  rings, the face's wires (any order, any orientation; the outer one is found here).
// Outputs: the polygon, with coordinates closer than the tolerance (see tolerance.h) snapped to one
//          value, vertices between collinear edges removed, outer ring counter-clockwise and holes
//          clockwise; *tolerance_out (optional) receives the tolerance used.
// Throws InputError, naming the wire, edge and coordinates, when: a coordinate is not finite; the
// face is too small or has zero or tiny area; an edge is not parallel to the X or Y axis or is
// shorter than the tolerance; the boundary doubles back, touches or crosses itself; a hole lies
// outside the outer wire or inside another hole.
RectilinearPolygon validate_rings(const std::vector<RawRing>& rings, double* tolerance_out = nullptr);

}  // namespace autoblock
