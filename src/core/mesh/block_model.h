// The block model of a general decomposition: the unknowns and the layout of its mapped mesh.
//
// Every finished part becomes four-sided pieces (region/block.h: a block is one piece, a template
// one piece per corner around its centroid). The model joins them: every piece's corners and side
// vertices, the template midpoints and centroids, are model vertices, shared by position (within
// kModelToleranceQuanta quanta); a vertex of one piece within that distance of the side of another
// (a T-junction) is imprinted into that side. Between consecutive
// vertices of a piece's loop lies a model edge, a straight segment shared by the one or two pieces
// it bounds. Each piece's four logical sides are the chains of model edges between its corners.
// Interval assignment gives every model edge a count (edge_intervals.h); the mesh puts that many
// intervals on every edge once (both neighbours use the same nodes: no hanging nodes) and fills every
// piece by transfinite interpolation (block_mesh.h).
#pragma once

#include <array>
#include <vector>

#include "core/geometry/point.h"
#include "core/region/block.h"
#include "core/region/region_policy.h"

namespace autoblock {

// How far, in quanta of the face's lattice, a model vertex may lie off a piece's side and still be on
// it: cut ends are rounded to the lattice (half a quantum in each coordinate), and so are the side's
// own ends, so a point of a side may sit about two quanta off the chord of its rounded ends (measured:
// 2.2 quanta on a face with a hole). The mesh's conformity is checked to the same tolerance.
constexpr double kModelToleranceQuanta = 3.0;
// The tolerance of a second model where the first's mesh fails its conformity check
// (mesh_region_decomposition): where many cuts end on one line, each splitting it at a point rounded to
// the lattice, the drift adds up (7.1 quanta on a perforated disk of 89 holes, whose radial lines carry
// scores of cut ends: at 3, hanging nodes, and `autoblock mesh` stopped with an internal error). Not the
// first model's: at 10, vertices a hair apart that the first keeps apart (the 24-bolt flange's, 5
// quanta) are taken for one, and its mesh fails. Ten quanta are about 5e-7 of the face's size.
constexpr double kWideModelToleranceQuanta = 10.0;

// Feet a hair apart (block_model's FeetSnap::near): nearer than this share of the shortest piece side
// at either.
constexpr double kFootSnap = 0.05;
// Feet a fair way apart (FeetSnap::far): nearer than this share of the longest piece side at either,
// where the move leaves the pieces' shapes (kFarFootShape) and order along the side.
constexpr double kFarFootSnap = 0.4;
// A piece whose foot moves keeps the least sine of its quadrilateral of corners above sin(20 degrees)
// and this share of what it was.
constexpr double kFarFootShape = 0.7;

// How block_model treats two templates' feet on the side their parts share: as the templates place
// them (placed); a hair apart made one (near); and, where the pieces keep their shapes, a fair way
// apart made one too (far: round a ring of templates, feet placed each from its own part admit no
// interval counts that balance).
enum class FeetSnap { placed, near, far };

struct ModelEdge {
  int a = 0, b = 0;  // vertex ids; the edge runs from a to b
  double length = 0.0;
  // An edge along an arc of the face's boundary (merge_arc_chains): the arc's index in FaceArcs and
  // the signed angle it turns from a to b about the arc's centre; -1 for any other edge.
  int arc = -1;
  double arc_sweep = 0.0;
};

// A logical side: model edges in order from one corner to the next (counter-clockwise around the
// piece), each run forward (a to b) or backward.
struct ModelSide {
  std::vector<int> edges;
  std::vector<char> forward;
};

struct ModelBlock {
  std::array<ModelSide, 4> sides;  // side k from corner k to corner k + 1
  int part = 0;                    // the finished part it belongs to (index into the decomposition's)
  bool from_template = false;
};

struct BlockModel {
  std::vector<Point2> vertices;
  std::vector<ModelEdge> edges;
  std::vector<ModelBlock> blocks;
  int parts = 0;  // finished parts
  FeetSnap feet = FeetSnap::placed;  // how it was made (block_model's snap)
  int snapped_feet = 0;  // template vertices made one with a neighbour's (block_model's snap)

  // Inputs: side. Output: its length, the sum of its edges'.
  double side_length(const ModelSide& side) const;
  // Output: true when feet a fair way apart were made one (FeetSnap::far, a foot moved).
  bool far_feet() const { return feet == FeetSnap::far && snapped_feet > 0; }
};

// Inputs:  decomposition, complete; rules, the block rules it was made with (side vertices);
//          quantum, the face's lattice spacing (Region::quantum), and tolerance_quanta, how many of
//          them a vertex may lie off a side and be on it; two_corner, as template_pieces
//          takes it (block.h); snap: two templates' feet on the side their parts share, a hair
//          apart (within kFootSnap of the shortest piece side at either), made one (near), and those
//          a fair way apart too (far: within kFarFootSnap of the longest piece side at either, the
//          pieces that move keeping kFarFootShape of their shape and their order along the side);
//          one moves to the other, along the side; a part's own vertex moves only a hair (near),
//          only inside the face, and only where every vertex on a side it turns stays on it (a
//          template's vertex there moves with it); one on the face's boundary never moves;
//          boundary_vertices, points of the face's boundary that are model vertices too (the face's
//          vertices its region leaves out, InputFace::straight_vertices), imprinted into the sides
//          they lie on like any other.
// Outputs: the model above, blocks part by part in the decomposition's order (a template's pieces
//          in template_pieces's order).
// Throws std::logic_error when the pieces do not fit together (an edge used by more than two
// pieces, a corner lost).
BlockModel block_model(const RegionDecomposition& decomposition, const BlockRules& rules, double quantum,
                       bool two_corner = false, FeetSnap snap = FeetSnap::near,
                       double tolerance_quanta = kModelToleranceQuanta,
                       const std::vector<Point2>& boundary_vertices = {});

// Along an arc of the face's boundary every sample of its polygon is a model vertex, so each chord
// would get its own whole number of intervals and the nodes would bunch where chords round up. This
// merges the chords of one piece's side that lie on one arc into one model edge wherever the vertex
// between them is no piece's corner, no other edge's end and no arc's end: its intervals then spread evenly in
// angle over the whole stretch (block_mesh.h), and its length is the chords' sum.
// Inputs: model (block_model's); arcs, the face's (FaceArcs). Output: model with those chains merged
//         (edges renumbered, sides updated; vertices kept, the merged ones unused).
void merge_arc_chains(BlockModel& model, const FaceArcs& arcs);

}  // namespace autoblock
