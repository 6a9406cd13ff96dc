// Finished parts of the general engine: blocks, and templates for parts no cut can finish.
//
// A vertex whose interior angle lies within `flat_tolerance` of 180 degrees is a side vertex (a
// block's side may bend there, as at a T-junction); every other vertex is a corner. A *block* is a
// part without holes, with no reflex vertex, and with exactly four corners whose angles lie in
// [min_corner, max_corner]. A rectangle is a block under any rules. A convex part that is not a
// block (a triangle, a pentagon, a quadrilateral with a corner out of range) may be finished with
// the *midpoint template*: its n corners, the midpoints of its n sides and its centroid make n
// quadrilaterals (a triangle: three quads around an interior point), whose centre node is irregular
// unless n = 4. The template's cost shows in the rewards (reward on regions) and in the mesh.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/region/region.h"

namespace autoblock {

struct BlockRules {
  double min_corner_degrees = 30.0;
  double max_corner_degrees = 150.0;
  double flat_tolerance_degrees = 20.0;
};

// Inputs: ring, a loop of a region; its vertex number i; rules.
// Output: true when the vertex is a side vertex (its angle within the flat tolerance of 180 degrees).
bool is_side_vertex(const Ring& ring, size_t i, const BlockRules& rules = {});

// Inputs:  region; rules.
// Outputs: the indices (into region.outer(), counter-clockwise) of the block's four corners, or
//          nothing when the region is not a block.
std::optional<std::array<int, 4>> block_corners(const Region& region, const BlockRules& rules = {});

inline bool is_block(const Region& region, const BlockRules& rules = {}) {
  return block_corners(region, rules).has_value();
}

// Inputs:  region; rules. Output: true when the midpoint template can finish it (convex, no holes).
bool template_applies(const Region& region);

// Inputs:  region, convex (template_applies); rules (which vertices are side vertices).
// Outputs: the template's quadrilaterals, one per corner of the region, each counter-clockwise
//          starting at the corner: the corner, the midpoint (by length along the boundary) of the
//          side it starts, the centroid, the midpoint of the side it ends. Side vertices lie on the
//          quads' boundary sides, which the four points here give as chords.
std::vector<std::array<Point2, 4>> template_quads(const Region& region, const BlockRules& rules = {});

// A four-sided piece of a finished part: its loop (counter-clockwise, side vertices included) and
// the positions of its four corners in the loop, in order. A block is one piece; a template is one
// piece per corner of the part.
struct QuadPiece {
  Ring ring;
  std::array<int, 4> corners{};
};

// Inputs:  region, convex (template_applies); rules (which vertices are side vertices).
// Outputs: the template's pieces, one per corner of the region, in the order of template_quads:
//          piece k runs from corner k along the region's boundary (through its side vertices) to the
//          midpoint of that side, to the centroid, to the midpoint of the side that ends at corner k,
//          and back along the boundary. A midpoint within the region's quantum of a side vertex is
//          that vertex. The pieces' loops share their spokes (midpoint to centroid) exactly.
std::vector<QuadPiece> template_pieces(const Region& region, const BlockRules& rules = {});

// The best minimum scaled Jacobian any all-quad mesh of a face can have, set by its corners: k quads
// meeting at a boundary corner of interior angle t split it into angles summing to t, the best being
// t / k each, whose scaled Jacobian is at most sin(t / k). So the bound is the minimum over the
// corners of the maximum over k >= 1 of sin(t / k) (1 for a right angle or a straight vertex; a
// 135-degree chamfer corner allows sin 67.5 = 0.924; a 30-degree corner sin 30 = 0.5).
// Inputs: loops, the face's outer loop and holes (the region on each loop's left: outer
//         counter-clockwise, holes clockwise). Output: the bound, in (0, 1].
double scaled_jacobian_bound(const std::vector<Ring>& loops);


// The minimum-area rectangle enclosing a region (its outer loop's convex hull; rotating calipers).
struct OrientedRectangle {
  Point2 center;
  Point2 axis{1.0, 0.0};  // unit vector along the first side
  double width = 0.0;     // along axis
  double height = 0.0;    // across it
  double longer_side() const { return width > height ? width : height; }
  double shorter_side() const { return width > height ? height : width; }
  double aspect_ratio() const { return longer_side() / shorter_side(); }
};

// Inputs: region (not empty). Output: its minimum-area enclosing rectangle. Ties between equal
//         areas go to the rectangle whose axis is closest to the X axis, so an axis-aligned
//         rectangle is its own bounding box.
OrientedRectangle min_area_rectangle(const Region& region);

}  // namespace autoblock
