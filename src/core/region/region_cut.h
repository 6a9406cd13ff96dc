// Cuts at any angle on a general region: the paper's full cut and the partial cut.
//
//   full     the whole line through `origin` along `direction`, clipped to the region: the region
//            is cut along every segment of the line that runs through its interior;
//   partial  the ray from `origin` along `direction`, ending at the first boundary it meets (a
//            T-junction there): the region is cut along that one segment.
// `origin` is a point on the region's boundary (a vertex, or a point on an edge); `direction` is any
// non-zero vector, so the angle is a real number. The split is decided by exact predicates and
// the pieces are rounded to the region's lattice (see region.h): a fast path on doubles (CGAL's
// exact predicates, crossings rounded to the lattice, exact constructions where that rounding is in
// doubt, a vertex within half a quantum of the cut line on it; region_cut.cpp) and, for whatever
// it cannot call, an arrangement of the boundary and the cut in CGAL's exact kernel. A cut that separates nothing (it misses the interior, runs along the
// boundary, or only joins the outer boundary to a hole, leaving a slit) changes nothing: the result
// is the region itself, N = 1. So does a cut that would leave a piece whose hole comes within one
// quantum of another of its loops (a cut nearly, but not exactly, along a hole's edge): rounding
// would make the loops touch, and such a piece is not a valid part; or a piece whose loops touch at a
// point (two chords meeting there: a line through a hole's corner, tangent to the hole). And so does
// a cut whose chords pass within 32 quanta of a vertex of the region that is not one of their ends
// (a chord grazing a vertex, a T-junction within 32 quanta of a corner, a neck narrower than that, a
// chord nearly along an edge leaving a strip that thin beside it: twice a sliver's width, so that no
// cut leaves a thin feature that only a sliver could finish) or that leaves a sliver (a piece whose
// area is at most eight quanta times its perimeter, a mean width of 16 quanta): OpenCASCADE, cutting
// the real face at the face's tolerance (region_replay.h), would read such a cut differently, and the
// mesher could not use an edge or a piece that small; clear of that, it makes exactly the engine's
// pieces.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/region/region.h"

namespace autoblock {

enum class CutKind { Full = 0, Partial = 1 };

// "full" or "partial".
std::string cut_kind_name(CutKind kind);

struct RegionCut {
  CutKind kind = CutKind::Full;
  Point2 origin;
  Point2 direction{1.0, 0.0};
  // Taken even when its chords pass within 32 quanta of a vertex (see above; never a sliver or a
  // pinched piece): only progress_action's last resort (region_candidates.h) sets it, on a part where
  // no cut keeps clear.
  bool forced = false;
};

// One straight segment a cut made through the interior.
struct Chord {
  Point2 a, b;
};

struct CutOutcome {
  std::vector<Region> pieces;  // N >= 1 pieces, ordered by their outer loops' vertices (lowest, then leftmost)
  std::vector<Chord> chords;   // the segments cut (empty when N = 1)
};

// Inputs:  region (not empty); cut, its origin on or near the region's boundary.
// Outputs: the pieces and the chords (in a canonical order: each from its lexicographically smaller
//          end, sorted), as above. The fast path splits the loops along the chords without an
//          arrangement; what it cannot call goes through cut_region_by_arrangement.
CutOutcome cut_region(const Region& region, const RegionCut& cut);

// Called with a cut's chords before its pieces are made; false stops the cut (see cut_region_if).
using ChordsCheck = std::function<bool(const std::vector<Chord>& chords)>;

// Inputs:  region (not empty); cut; proceed (may be empty: never stops).
// Outputs: cut_region's outcome, or nothing when proceed, called with the cut's chords (in canonical
//          order; empty: the cut separates nothing) as soon as the fast path knows them, returned
//          false. It is called for a region without holes and a cut not forced, where the outcome is
//          a function of the chords (cuts with the same chords have the same pieces): a search cuts
//          each set of chords once (a ray from one vertex to another and the ray back, a full cut
//          whose line runs through the part once and the partial cut along it).
std::optional<CutOutcome> cut_region_if(const Region& region, const RegionCut& cut, const ChordsCheck& proceed);

// The same by the arrangement for every cut (the general path; tests compare the two).
CutOutcome cut_region_by_arrangement(const Region& region, const RegionCut& cut);

// Inputs: region. Output: true when a vertex of one of its loops lies within one quantum of another
//         loop: the loops touch (a cut nearly along a hole's edge leaves a gap thinner than the
//         lattice, which rounding closes; such a cut's pieces are refused).
bool loops_touch(const Region& region);

// Inputs:  region; origin on its boundary; direction.
// Outputs: true with *hit set when the ray from origin along direction first runs into the
//          interior and then meets the boundary at *hit (the partial cut's end point, rounded to
//          the lattice); false when the ray leaves at once or runs along the boundary.
bool partial_cut_end(const Region& region, Point2 origin, Point2 direction, Point2* hit);

// Inputs:  region; p, a point; u, a unit direction.
// Outputs: a point where the line through p along u crosses the region's outer loop (the origin of
//          a full cut along that line: cut_region clips the whole line to the region), or nothing.
std::optional<Point2> line_meets_outer(const Region& region, Point2 p, Point2 u);

}  // namespace autoblock
