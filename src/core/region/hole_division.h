// Dividing a part with many holes (a tube sheet, a filter, a perforated disk) along the ligaments
// between them, before any search.
//
// Such a part has thousands of candidate cuts (every hole's samples, every direction), each as costly
// as the part is large: the search spent its budget on the first parts and finished the rest greedily,
// leaving slivers (a disk with 89 holes: 1300 blocks, least scaled Jacobian 0.05-0.17, 10 s, and a
// different mesh each run). An analyst cuts along the ligaments instead, until each hole has a cell of
// its own, and meshes each cell on its own (an O-grid where the cell is a quadrilateral, block.h).
// divide_holes chooses such a cut by geometry alone, scoring no cut:
//   lines    full cuts (region_cut.h) along lines that cross no hole and have holes on both sides:
//            along a direction u, each hole's extent across u (its vertices projected on u's normal)
//            is an interval; where the intervals, sorted, leave a gap, the line along u through the
//            gap's middle separates the holes before it from those after;
//   directions  the part's long straight edges (at least a tenth of its minimum-area rectangle's
//            longer side, the longest four) and their normals, the axes of that rectangle, and the
//            directions from each hole to its nearest neighbour and their normals (the six most
//            common within 2 degrees: a grid's rows, a staggered grid's, a polar pattern's);
//   radial   lines through the centre of the circles that make most of the part's outer loop (a
//            flange's rim and bore, or a sector of them: each run of three vertices close together on
//            a circle votes for its centre, and one centre must hold 35 % of the loop's length), when
//            that centre lies in a hole (the bore, which the line cuts across) or outside the part
//            (the notch a cut bore left): the holes' angular extents seen from the centre, modulo a
//            half turn, leave gaps, and the line through a gap's middle keeps half a radius from every
//            hole. Lines that would meet inside the part (a disk without a bore) are not made: they
//            would leave its pieces a sharp corner there. A flange divides into one sector per bolt
//            hole;
//   choice   the best by, in turn: the gap's clearance (half its width) at least half the larger
//            radius of the two holes beside it (room for their O-grids: ogrid_template), radial, the
//            line parallel or square to a long straight edge of the part (cells with right-angled corners),
//            more holes on the smaller side (a balanced division: as few levels as holes' logarithm),
//            the larger clearance relative to that radius. No line nearer a hole than a tenth of that
//            radius is taken: a staggered grid with ligaments of 0.35 diameters leaves 0.17 between
//            its rows, and those cells still beat the search's (0.66 against 0.06 on such a plate).
//            The cut is the first line in that order that cut_region makes (it refuses a line that
//            grazes a vertex or leaves a sliver), that meets the boundary at 60 degrees or more at
//            every end of its chords (no sharp wedge between the line and a disk's rim or an earlier
//            line), and that leaves every piece fewer holes; after 32 lines cut in vain, none.
// A hole's extent is its polygon's (circles reach the engine as their samples, circular_arc.h); the
// true circle bulges past it by the sagitta, far less than any clearance taken.
// Measured (BENCHMARKS.md, "Perforated plates", "Flanges"): grids, staggered grids and scattered holes
// in plates divide into good cells, flanges into sectors; rings of holes turned against each other on
// a disk leave no line clear of every hole until the disk's parts are small, so the search still cuts
// their first parts and such faces gain less.
// The cut is the same for the same part (no randomness, no clock), so the division repeats exactly.
#pragma once

#include <optional>

#include "core/region/region_cut.h"

namespace autoblock {

// The search divides a part with at least this many holes (region_search.h); a part with fewer goes
// to divide_sector (below), and one with two holes that a division left, where that finds no line, to
// divide_holes too, taking only a line with room for both holes' O-grids (two holes close together, a
// line threaded between them leaves slivers); only then does the search cut it, its candidates
// holding the cuts between two holes (region_candidates.h).
constexpr int kDivideHoles = 3;

struct HoleDivision {
  RegionCut cut;
  CutOutcome outcome;  // cut_region's: two pieces or more, each with fewer holes than the part
  // The centre of the part's arcs that the division found (its pieces' hint for divide_sector), if any.
  std::optional<Point2> centre;
};

// Inputs:  part; hint, the centre its parent's division found (HoleDivision::centre), the radial
//          lines' centre where the part's own arcs give none (a part of a flange cut off by chords,
//          whose arcs are too short to show it); roomy, only lines that leave the holes beside them
//          room for their O-grids (a clearance of half the larger radius).
// Outputs: the division cut above, its outcome and the centre, or nothing when the part has fewer than two holes
//          or no line in the directions above separates them (holes that overlap across every
//          direction, a bore in the middle of a bolt circle, lines that cut_region refuses or that
//          meet the boundary too obliquely).
std::optional<HoleDivision> divide_holes(const Region& part, std::optional<Point2> hint = std::nullopt, bool roomy = false);

// A flange's sector with a bolt hole or two (fewer than kDivideHoles: divide_holes leaves it to the
// search) is wider than the hole's cell: divide_holes's radial lines run through the middles of the
// gaps between the holes, so a flange of four bolt holes leaves quarter rings, too wide for an O-grid
// with straight box sides (ogrid_template). An analyst cuts a square cell about each hole instead and
// leaves the ring between the cells to blocks. Where the centre of the part's arcs lies away from the
// part as for divide_holes's radial lines (the centre of most of its outer loop, or of a tenth of it
// where that loop runs along two arcs about it of radii 1.2 apart, a narrow sector's bore and rim;
// else the centre its parent's division found: a piece's arcs, polygonised in steps of up to 15
// degrees and cut short, vote for centres far apart), divide_sector cuts along the first of these lines that keeps half a radius
// from every hole, meets the boundary at 60 degrees or more and leaves no piece smaller than a
// quarter of a hole's square cell:
//   bisector  between two holes (not the bore), the radial bisector of their directions from the
//             centre, leaving fewer holes in each piece (a sector of two bolt holes halved);
//   between   between two holes in line (a flange's two bolt circles), the chord square to their
//             bisector halfway between them, leaving fewer holes in each of its two pieces;
//   cell side for each hole, radially at half a square cell's angle from its direction, on either
//             side: the cell as wide, round the hole's circle about the centre, as the part is deep
//             along the ray through the hole;
//   cell end  where the part is more than 1.5 times as deep along a hole's ray as it is wide across
//             the hole (a narrow sector), the chord square to the ray at the end of the hole's square
//             cell (as long as the part is wide there, kept inside the part), the larger leftover first;
//             a chord must leave two pieces.
// The cells that chords leave have one side along the bore or the rim: the O-grid takes them too.
// A part with no such centre (a plate's strip between two of divide_holes's lines) has cell ends
// only: along each axis of its minimum-area rectangle, where it is longer through a hole than the
// hole's square cell and a quarter of one, the lines square to the axis at the ends of that cell,
// taken where the hole's piece then takes an O-grid or is still that long (a hole too
// near the strip's sides for an O-grid is left to the search). In a strip narrower than a hole's
// O-grid room (a staggered grid's row) such a line keeps from the hole what the strip's sides keep
// (at least a tenth of a radius): the cell is a tight one (ogrid_template), where tight
// O-grids are allowed.
// Measured (BENCHMARKS.md, "Flanges: square cells", "Two bolt circles"): a flange of four bolt holes
// 0.41 -> 0.83, one bolt circle of square sectors 0.81-0.82 -> 0.93-0.95; flanges of two bolt
// circles 0.49-0.57 -> 0.81-0.87 of the bound.
// Inputs:  part; hint, the centre its parent's division found (HoleDivision::centre), taken where the
//          part's own arcs give none (as for divide_holes); tight_ogrid, false: no cell left for a
//          tight O-grid (ogrid_template), as before they were made (RegionSearchOptions::tight_ogrid).
// Outputs: the cut, its outcome and the centre (none for a strip), or nothing (no hole, every hole's
//          cell already as narrow as that, or no line that cut_region makes with those checks).
std::optional<HoleDivision> divide_sector(const Region& part, std::optional<Point2> hint = std::nullopt,
                                          bool tight_ogrid = true);

}  // namespace autoblock
