// A planar region bounded by axis-parallel edges: one outer ring and any number of holes.
//
// Rings hold corners only (no two consecutive edges collinear) and are implicitly closed. The
// outer ring runs counter-clockwise and holes clockwise, so the region is always on the left.
#pragma once

#include <vector>

#include "core/geometry/point.h"

namespace autoblock {

using Ring = std::vector<Point2>;

struct RectilinearPolygon {
  Ring outer;
  std::vector<Ring> holes;
};

// Inputs: ring, implicitly closed. Output: shoelace area, positive when counter-clockwise.
double signed_area(const Ring& ring);

// Inputs: polygon. Output: area of the region (outer minus holes).
double polygon_area(const RectilinearPolygon& polygon);

// Inputs: ring (non-empty). Output: its bounding box.
Box ring_bbox(const Ring& ring);

// Inputs: point p, ring (simple, implicitly closed). Output: true when p is strictly inside
// (even-odd rule; a point on the ring is not inside).
bool point_in_ring(Point2 p, const Ring& ring);

}  // namespace autoblock
