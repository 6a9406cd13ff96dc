// Finished parts of the general engine: blocks, and templates for parts no cut can finish.
//
// A vertex whose interior angle lies within `flat_tolerance` of 180 degrees is a side vertex (a
// block's side may bend there, as at a T-junction); every other vertex is a corner. A *block* is a
// part without holes, with no reflex vertex nor concave arc with an open end (concave_runs), and with
// exactly four corners whose angles lie in [min_corner, max_corner], and, when its sides bend (more
// than 30 degrees in all: arcs), whose Coons patch neither folds (a convex side facing a deep concave
// one) nor squeezes its cells below half the sine of min_corner (a rounded corner in a side facing a
// straight one). A rectangle is a block under any rules. A convex part that is not a
// block (a triangle, a pentagon, a quadrilateral with a corner out of range) may be finished with
// the *template*: its n corners, a centre point (the centre of the largest circle inside the
// polygon of its corners) and, on each side, the foot of the perpendicular from the centre (kept
// within the side's middle half) make n quadrilaterals (a triangle: three quads around an interior
// point). Where the feet fall inside their sides, each quad has right angles at the feet and the
// angles t and 180 - t at the corner and the centre, so its scaled Jacobian is the corner's own
// sine: the template costs no quality beyond the part's corners. Its centre node is irregular unless
// n = 4; that cost shows in the rewards (reward on regions) and in the mesh.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "core/geometry/circular_arc.h"
#include "core/region/region.h"

namespace autoblock {

struct BlockRules {
  double min_corner_degrees = 30.0;
  double max_corner_degrees = 150.0;
  double flat_tolerance_degrees = 20.0;
  // Not what a block is but which cuts make progress (region_candidates.h, part_complexity): true
  // makes a part with fewer than three corners that the smooth template does not take (a wedge with a
  // rounded end and a rounded tip, say) count as complex, so that the cuts leaving simpler pieces make
  // progress and the search may cut it instead of finishing it with the usual template's fallback
  // corners. One of `autoblock mesh`'s later tries (kSearchTries).
  bool cut_smooth_parts = false;
};

// Inputs: ring, a loop of a region; its vertex number i; rules.
// Output: true when the vertex is a side vertex (its angle within the flat tolerance of 180 degrees).
bool is_side_vertex(const Ring& ring, size_t i, const BlockRules& rules = {});

// Inputs: ring, a loop of a region; its vertex number i; rules.
// Output: is_side_vertex and is_reflex_vertex (region.h) of the vertex, from one pair of products.
struct VertexShape {
  bool side = false;
  bool reflex = false;
};
VertexShape vertex_shape(const Ring& ring, size_t i, const BlockRules& rules = {});

// A concave run of a loop: consecutive reflex side vertices that turn inwards by more than the flat
// tolerance in all (a concave arc, circular_arc.h: a reflex fillet, or a hole's rounded corner once a
// cut has opened the hole). Each end of it is *open* where the boundary runs on smoothly from it (side
// vertices only) for more than 1.5 of the run's longest chord before the next corner: a fillet's
// tangent join with its edge, which acts as a reflex corner; *closed* where a corner follows at once
// (a cut square to the arc there), which a block's or a template's side may end at.
struct ArcRun {
  size_t first = 0, last = 0;  // the run's first and last vertex (the ring's order, cyclically)
  double turn = 0.0;           // radians, > the flat tolerance
  bool open_before = false, open_after = false;
};
// Inputs: ring, a loop of a region; rules. Output: its concave runs, in the ring's order (none on a
//         loop of side vertices only: a round hole).
std::vector<ArcRun> concave_runs(const Ring& ring, const BlockRules& rules = {});

// A convex run: the same of side vertices that turn outwards (a convex arc: a fillet), broken where
// an edge is more than twice as long as the longer of the edges beside it (the straight edge between
// two fillets). One with an open end inside a block's or a template's side (a fillet whose ends run
// on into straight edges) squeezes the quads around it: it must be cut square at its open ends first
// (a quarter-round fillet ends as a sector, three corners around its arc, for the template) when it
// turns by more than kOpenConvexLimit and at most kOpenConvexMax. (A fillet of more than that rounds
// an acute corner: cut square at its ends, it would leave a sharp corner at its centre, 180 degrees
// less its turn; it stays in a side.)
// Inputs: ring, a loop of a region; rules. Output: its convex runs, in the ring's order (none on a
//         loop of side vertices only: a disk, a rounded rectangle).
std::vector<ArcRun> convex_runs(const Ring& ring, const BlockRules& rules = {});
constexpr double kOpenConvexLimit = 60.0 * M_PI / 180.0;
constexpr double kOpenConvexMax = 120.0 * M_PI / 180.0;

// Inputs: run, a convex run. Output: true when it turns by more than kOpenConvexLimit and at most
//         kOpenConvexMax, with an open end: what the policies cut square at its open ends.
inline bool open_fillet(const ArcRun& run) {
  return (run.open_before || run.open_after) && run.turn > kOpenConvexLimit && run.turn <= kOpenConvexMax;
}

// Inputs: ring; rules. Output: true when one of its convex runs is an open fillet (open_fillet).
bool open_convex_run(const Ring& ring, const BlockRules& rules = {});

// Inputs: region; rules. Output: true when its outer loop has such a run (open_convex_run) and three
//         corners or more: the policies cut it square at the run's open ends (region_candidates.h)
//         rather than finish it with the usual template, whose sides would take the run whole. (The
//         smooth template, for fewer corners, and the template's legality, template_applies, are
//         unchanged.)
bool fillet_needs_cuts(const Region& region, const BlockRules& rules = {});

// A concave run of more than this (radians) counts as a reflex corner even when both its ends are
// closed (region_candidates.h): no block side, nor a template side, takes it whole.
constexpr double kClosedRunLimit = 100.0 * M_PI / 180.0;

// Inputs:  region; rules.
// Outputs: the indices (into region.outer(), counter-clockwise) of the block's four corners, or
//          nothing when the region is not a block.
std::optional<std::array<int, 4>> block_corners(const Region& region, const BlockRules& rules = {});

inline bool is_block(const Region& region, const BlockRules& rules = {}) {
  return block_corners(region, rules).has_value();
}

// Inputs:  region. Output: true when the template can finish it: no holes, convex but for side
//          vertices (within the default flat tolerance) that turn slightly inwards, or but for one
//          concave run closed at both ends that turns by at most kClosedRunLimit (the corner piece of
//          a reflex fillet, cut square to the arc at its ends: five corners and the arc around a
//          five-valent centre) where the template's centre and spokes keep clear of the arc; or one
//          round hole that the O-grid template takes (ogrid_template).
bool template_applies(const Region& region);

// A smooth part (fewer than three corners: a disk, a rounded rectangle, a D-shape; arcs reach the
// engine as chains of side vertices, circular_arc.h) gets the disk's template instead: four of its
// boundary vertices (those nearest the corners of its minimum-area rectangle) joined by spokes to
// an inner quadrilateral halfway to its centroid: five pieces, the inner one last. Each of the four
// boundary vertices splits a straight (or nearly straight) boundary into two corners of about 90
// degrees; the inner quadrilateral's corners are three-valent interior vertices. It applies only
// when each piece's quadrilateral of corners is convex with angles within [20, 160] degrees. A long
// part's (a finger's rounded end) would fold halfway to the centroid: its inner corners are then
// the four vertices moved into the minimum-area rectangle shrunk by a quarter of its shorter side
// (or 0.15, 0.35 of it), as far from the ends as from the sides; when none of those is well shaped
// either, the template is the usual one (whose third corner, on a smooth end, meets the boundary at
// nearly 180 degrees).
// Inputs: region; rules. Output: true when the smooth template applies (template_pieces makes it).
bool smooth_template(const Region& region, const BlockRules& rules = {});

// A part with exactly two corners P and Q (the rounded end of a wedge or a finger cut across, a
// D-shape, the cap a cut leaves over a rounded top) may get the *two-corner template* instead: every
// quad mesh of such a part needs two irregular interior vertices (its corners kept whole, as the
// smooth template does not keep them), so it has two, I1 and I2, joined to each other and each to a
// point on each side: M1, M2 on the side from P to Q, X2, X1 on the side from Q back to P. Four pieces:
// P's (P, M1, I1, X1), the first side's (M1, M2, I2, I1), Q's (M2, Q, X2, I2) and the second side's (X2,
// X1, I1, I2). The side points stand at a fraction f and 1 - f of their side's length (the side vertex
// nearest, within a tenth of the side, where there is one: an arc's sample stays on its circle; else
// a point on the straight side); I1 and I2 lie between the sides' points and are drawn towards each
// other. Of a few such placements (f, how far across, how far drawn) the one whose pieces' Coons
// patches have the best least scaled Jacobian is made, when every piece is a convex quadrilateral of
// corners with angles in [20, 160] degrees and the spokes keep clear of the boundary. template_pieces
// makes it, asked to (two_corner), where it beats the smooth template or the usual template's
// fallback corners by that same measure: a poor mesh is made again so (mesh_region_decomposition).
// It is not the template's default, which the search's rewards value: made so, it raised the mean
// over the benchmark's faces, but the searches took other paths and lost badly on a few faces.
// Inputs: region; rules. Output: true when the two-corner template applies.
bool two_corner_template(const Region& region, const BlockRules& rules = {});
// Inputs: region; rules. Output: true when the two-corner template applies and its pieces score better
//         than the template's default pieces (template_pieces with two_corner makes it).
bool two_corner_improves(const Region& region, const BlockRules& rules = {});

// A part with one round hole (issue 13: a circle reaches the engine as a ring of side vertices,
// circular_arc.h), or any smooth convex one (a slot), and four convex corners of 60-120 degrees joined
// by straight sides, or sides along arcs that bend by at most 60 degrees each (a flange's cell: an
// annular sector; or one arc over a straight side, a cell that a chord between two bolt circles cut
// off from the bore or the rim), gets the O-grid template: a box around the hole, its side k parallel to the chord
// of the part's side k, halfway between the hole and that side (its nearest vertex: a bore's arc bulges
// towards the hole) but at most one radius (the hole's smallest reach from its centroid) beyond the
// hole; four pieces between the box and the hole (each box corner
// joined to the hole's vertex in its direction from the hole's centroid), four between the box and
// the sides (the box corners' feet on the sides), and four at the part's corners: twelve pieces in
// that order, every corner of the part, foot and box side a right angle on a rectangle. The box
// corners are the five-valent vertices that a quad mesh of a part with a round hole needs
// (topology_jacobian_bound). It applies only where every side leaves room (the hole at least half a
// radius and 64 quanta from it), the feet fall inside their sides, and every piece's quadrilateral of
// corners is convex with angles within [20, 160] degrees; with curved sides (their feet on the sides'
// polygons), also where the pieces' Coons patches keep a scaled Jacobian of 0.45 (a sector as long
// round its middle as it is deep gives 0.48-0.54 as it spans 50-36 degrees, a plate's O-grid
// 0.59-0.65; a wider one's box is a trapezoid whose ring pieces skew: 0.42 at 120 degrees). With
// curved sides the box may lie up to 1.5 radii beyond the hole, and where the feet square to a side
// fall outside it (a deep, narrow sector, its radial sides converging on the bore) each foot is
// where the box line through the box corner meets the side instead.
// A tight cell (a staggered grid's: no side with that room, but every side at least a tenth of a
// radius and 64 quanta from the hole and at most a radius) gets its own sides as
// the box: four pieces, each a side of the part, the spokes from its two corners to the hole's
// vertices nearest them, and the hole between them. Each corner, split by the line to the hole's
// centre, keeps angles of 38 degrees at least on both sides (sine 0.62: a rhombus's 60- or 70-degree
// corners are refused; taken at 33 degrees, such cells of a staggered plate meshed at 0.51 where the
// search's own cuts gave 0.69), every piece's quadrilateral of corners within [20, 160] degrees and
// its Coons patch 0.45 at least. BENCHMARKS.md, "Tight cells".
// Inputs: region; rules. Output: true when the O-grid template applies (template_pieces makes it).
bool ogrid_template(const Region& region, const BlockRules& rules = {});
// Inputs: region; rules. Output: true when the O-grid that applies is a tight cell's (four pieces).
bool tight_ogrid_template(const Region& region, const BlockRules& rules = {});
// Inputs: region; rules. Output: true when the O-grid that applies has its box (twelve pieces).
bool roomy_ogrid_template(const Region& region, const BlockRules& rules = {});
// The O-grid's room between the hole and every side of its part, in the hole's radii (divide_holes'
// roomy lines leave both holes that much, hole_division.h). 0.35 for the O-grid alone was measured and
// not kept: the 30 flanges fell from 0.8564 to 0.8513, and a perforated plate's every try admitted no
// interval counts.
constexpr double kOgridClearance = 0.5;

// Inputs:  region, convex (template_applies); rules (which vertices are side vertices).
// Outputs: the template's quadrilaterals, one per corner of the region, each counter-clockwise
//          starting at the corner: the corner, the foot on the side it starts, the centre, the foot
//          on the side it ends. Side vertices lie on the quads' boundary sides, which the four points
//          here give as chords.
std::vector<std::array<Point2, 4>> template_quads(const Region& region, const BlockRules& rules = {});

// A four-sided piece of a finished part: its loop (counter-clockwise, side vertices included) and
// the positions of its four corners in the loop, in order. A block is one piece; a template is one
// piece per corner of the part.
struct QuadPiece {
  Ring ring;
  std::array<int, 4> corners{};
};

// Inputs:  piece; k, one of its corners (0-3).
// Outputs: the sine and cosine of the angle at corner k of its quadrilateral of corners (the sine
//          negative where it turns clockwise; -1 and 1 for a degenerate corner).
struct CornerAngle {
  double sine = 0.0, cosine = 1.0;
};
CornerAngle piece_corner_angle(const QuadPiece& piece, int k);

// Inputs:  region, convex (template_applies); rules (which vertices are side vertices).
// Outputs: the template's pieces, one per corner of the region, in the order of template_quads:
//          piece k runs from corner k along the region's boundary (through its side vertices) to the
//          foot on that side, to the centre, to the foot on the side that ends at corner k, and back
//          along the boundary. A foot within the region's quantum of a side vertex is that vertex, as is
//          one within a twentieth of the shorter edge beside the vertex (not a hair-thin edge between
//          them, whose quads would be triangles with an edge of no length).
//          The pieces' loops share their spokes (foot to centre) exactly. A smooth part's template
//          (smooth_template) and the O-grid (ogrid_template) give their own pieces instead;
//          two_corner: a part with two corners the two-corner template's where it scores better
//          (two_corner_improves). Throws std::logic_error for a part with holes that the O-grid does
//          not take.
std::vector<QuadPiece> template_pieces(const Region& region, const BlockRules& rules = {}, bool two_corner = false);

// The best minimum scaled Jacobian any all-quad mesh of a face can have, set by its corners: k quads
// meeting at a boundary corner of interior angle t split it into angles summing to t, the best being
// t / k each, whose scaled Jacobian is at most sin(t / k). So the bound is the minimum over the
// corners of the maximum over k >= 1 of sin(t / k) (1 for a right angle or a straight vertex; a
// 135-degree chamfer corner allows sin 67.5 = 0.924; a 30-degree corner sin 30 = 0.5).
// Inputs: loops, the face's outer loop and holes (the region on each loop's left: outer
//         counter-clockwise, holes clockwise). Output: the bound, in (0, 1].
double scaled_jacobian_bound(const std::vector<Ring>& loops);
// The same for a face with circular arcs (loops hold their samples): the bound of the true boundary,
// where a vertex inside an arc is smooth (no corner) and an arc's end meets its neighbour at the
// arc's tangent (a tangent join counts as 180 degrees).
double scaled_jacobian_bound(const std::vector<Ring>& loops, const FaceArcs& arcs);

// A true corner of a face's boundary: where it is, its interior angle (radians, in (0, 2 pi), the
// arcs' tangents taken there) and the arcs that end at it (arcs.arcs' index, the one arriving along
// the loop and the one leaving; -1: a straight edge).
struct BoundaryCorner {
  Point2 at;
  double angle = 0.0;
  int arc_in = -1, arc_out = -1;
};
// Inputs: loops, arcs, as for scaled_jacobian_bound. Output: the face's true corners, loop by loop:
//         every vertex but those inside an arc and the tangent joins of arcs with their neighbours.
std::vector<BoundaryCorner> boundary_corners(const std::vector<Ring>& loops, const FaceArcs& arcs);
// Inputs: loops, arcs, as for scaled_jacobian_bound. Output: boundary_corners' angles.
std::vector<double> boundary_corner_angles(const std::vector<Ring>& loops, const FaceArcs& arcs);

// The bound of the face's corners and its topology together (<= scaled_jacobian_bound). In an all-quad
// mesh of a face with h holes, sum over interior vertices of (4 - valence) plus sum over boundary
// vertices of (3 - valence) is 4 (1 - h). A corner split into k quads adds 2 - k, a smooth boundary
// vertex with two quads nothing; whatever the corners leave over, D, interior vertices must make up:
// D > 0 needs a three-valent one (three angles summing to 360 degrees: one at least 120, scaled
// Jacobian at most sin 120 = 0.866), D < 0 a five-valent one or more (one angle at most 72: sin 72 =
// 0.951). So a disk, a rounded rectangle or a rectangle with one convex fillet cannot pass 0.866, a
// plate with a round hole 0.951, whatever their corner bound (1). The bound is the best over the
// corners' splits k of min(min over corners of sin(t / k), that cost).
// Inputs: loops, arcs, as for scaled_jacobian_bound. Output: the bound, in (0, 1].
double topology_jacobian_bound(const std::vector<Ring>& loops, const FaceArcs& arcs);

// The mesh preset's block rules for a face: a block's corners must lie within
// [asin(f B), 180 - asin(f B)] degrees, B the face's bound (scaled_jacobian_bound), so that no block
// corner caps the mesh below f B. A chamfer's 135-degree corner (B = sin 67.5 = 0.924) is then no
// block corner and must be split; a face with a 20-degree corner (B = 0.342) keeps it in a block
// instead of a template. The flat tolerance is the default's.
// Inputs: loops, the face's outer loop and holes; fraction f in (0, 1]. Output: the rules.
constexpr double kMeshCornerFraction = 0.85;
BlockRules mesh_block_rules(const std::vector<Ring>& loops, double fraction = kMeshCornerFraction);


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
