#include "core/region/region_candidates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace autoblock {
namespace {

Point2 unit(Point2 d) {
  const double len = std::hypot(d.x, d.y);
  return {d.x / len, d.y / len};
}

double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }

// True when a direction d at vertex v points strictly into the region, whose boundary arrives
// from p and leaves towards n with the region on the left: d lies strictly inside the interior angle,
// swept counter-clockwise from the outgoing edge to the incoming one (reversed). By the signs of
// cross products of unit vectors (no trigonometry on this hot path), each kept 1e-12 clear of the
// edges' directions.
// Inputs: in, out, the unit vectors from v to p and to n; u, the unit vector of d.
bool points_inside(Point2 in, Point2 out, Point2 u) {
  constexpr double margin = 1e-12;
  const double turn = cross(out, in);
  if (turn > 0.0 || (turn == 0.0 && dot(out, in) < 0.0)) {
    // A convex (or flat) corner: d left of `out` and right of `in`.
    return cross(out, u) > margin && cross(u, in) > margin;
  }
  // A reflex corner: anything but the closed exterior wedge from `in` to `out`; a direction along
  // either edge is not inside.
  if (dot(u, in) > 0.0 && std::fabs(cross(u, in)) <= margin) return false;
  if (dot(u, out) > 0.0 && std::fabs(cross(out, u)) <= margin) return false;
  return !(cross(in, u) >= 0.0 && cross(u, out) >= 0.0);
}

// Inputs: part with two holes or more; smooth, which of them are smooth (circles, slots); ax, ay, the
//         axes of its minimum-area rectangle.
// Output: full cuts that separate two smooth holes: for every pair whose extents along an axis leave
//         a gap, the line across that axis through the gap's middle.
void hole_separating_cuts(const Region& part, const std::vector<char>& smooth, Point2 ax, Point2 ay,
                          std::vector<RegionAction>* actions) {
  const std::vector<Ring>& holes = part.holes();
  for (const Point2 u : {ax, ay}) {
    std::vector<std::pair<double, double>> extent;
    for (const Ring& hole : holes) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const Point2& v : hole) {
        lo = std::min(lo, dot(u, v));
        hi = std::max(hi, dot(u, v));
      }
      extent.push_back({lo, hi});
    }
    for (size_t i = 0; i < holes.size(); ++i) {
      for (size_t j = 0; j < holes.size(); ++j) {
        if (i == j || !smooth[i] || !smooth[j] || !(extent[i].second < extent[j].first)) continue;
        const double mid = 0.5 * (extent[i].second + extent[j].first);
        const Point2 along{-u.y, u.x};
        if (const auto origin = line_meets_outer(part, {mid * u.x, mid * u.y}, along)) {
          actions->push_back({RegionAction::Kind::Cut, {CutKind::Full, *origin, along}});
        }
      }
    }
  }
}

}  // namespace

bool operator<(const Complexity& a, const Complexity& b) {
  if (a.holes != b.holes) return a.holes < b.holes;
  if (a.reflex != b.reflex) return a.reflex < b.reflex;
  return a.corners < b.corners;
}

Complexity part_complexity(const Region& part, const BlockRules& rules) {
  Complexity c;
  c.holes = static_cast<int>(part.holes().size());
  for (int k = 0; k < part.loop_count(); ++k) {
    const Ring& ring = part.loop(k);
    bool concave_side = false;
    int convex_side = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
      const VertexShape shape = vertex_shape(ring, i, rules);
      if (shape.side) {
        concave_side = concave_side || shape.reflex;
        convex_side += !shape.reflex;
        continue;
      }
      if (shape.reflex) ++c.reflex;
      ++c.corners;
    }
    // A long convex arc's open ends act as corners (a fillet in the middle of a side: two).
    if (convex_side >= 3) {
      for (const ArcRun& run : convex_runs(ring, rules)) {
        if (open_fillet(run)) c.corners += static_cast<int>(run.open_before) + static_cast<int>(run.open_after);
      }
    }
    if (!concave_side) continue;  // no concave run (every run is made of such vertices)
    // A concave arc's open ends act as reflex corners (a fillet: two), and so does a long one.
    for (const ArcRun& run : concave_runs(ring, rules)) {
      c.reflex += static_cast<int>(run.open_before) + static_cast<int>(run.open_after);
      if (!run.open_before && !run.open_after && run.turn > kClosedRunLimit) ++c.reflex;
    }
  }
  // A part that only the usual template's fallback corners could finish (block.h, cut_smooth_parts).
  if (rules.cut_smooth_parts && c.holes == 0 && c.reflex == 0 && c.corners < 3 && part.outer().size() > 3 &&
      !smooth_template(part, rules)) {
    c.corners += kSmoothPartCorners;
  }
  return c;
}

bool makes_progress(const Region& part, const std::vector<Region>& pieces, const BlockRules& rules) {
  return makes_progress(part_complexity(part, rules), pieces, rules);
}

bool makes_progress(const Complexity& before, const std::vector<Region>& pieces, const BlockRules& rules) {
  if (pieces.size() < 2) return false;
  for (const Region& piece : pieces) {
    if (!(part_complexity(piece, rules) < before) && !is_block(piece, rules)) return false;
  }
  return true;
}

std::vector<RegionAction> region_candidates(const Region& part) {
  std::vector<RegionAction> actions;
  const OrientedRectangle frame = min_area_rectangle(part);
  const Point2 ax = frame.axis, ay{-frame.axis.y, frame.axis.x};
  const bool convex = part.is_convex();
  // Scratch lists, cleared per vertex (their storage kept: no allocation per vertex).
  std::vector<Point2> directions, partial, full, partial_unit, full_unit;
  std::vector<char> smooth_holes;
  for (int k = 0; k < part.loop_count(); ++k) {
    const Ring& ring = part.loop(k);
    const size_t m = ring.size();
    // A smooth hole (a circle, a slot: every vertex a side vertex): at its vertices only the cuts
    // along the bisector, square to the hole; the others run nearly along it.
    bool smooth_hole = k > 0;
    for (size_t i = 0; i < m && smooth_hole; ++i) smooth_hole = is_side_vertex(ring, i);
    if (k > 0) smooth_holes.push_back(smooth_hole);
    for (size_t i = 0; i < m; ++i) {
      const Point2 p = ring[(i + m - 1) % m], v = ring[i], n = ring[(i + 1) % m];
      const Point2 e_in = unit({v.x - p.x, v.y - p.y}), e_out = unit({n.x - v.x, n.y - v.y});
      const Point2 to_p{-e_in.x, -e_in.y};
      Point2 bisector = unit({e_out.x + to_p.x, e_out.y + to_p.y});
      if (!(std::hypot(bisector.x, bisector.y) > 0.5)) bisector = {-e_out.y, e_out.x};  // a flat vertex
      if (!points_inside(to_p, e_out, unit(bisector))) bisector = {-bisector.x, -bisector.y};
      if (smooth_hole) {
        directions.assign({bisector});
      } else {
        directions.assign({bisector, {-e_in.y, e_in.x}, {-e_out.y, e_out.x}, ax, {-ax.x, -ax.y}, ay, {-ay.x, -ay.y}});
        // Its edges' extensions too, but at a side vertex (an arc's sample, a cut's end on an edge),
        // where they run along the boundary (outside, or nearly along a concave arc: slivers).
        if (!is_side_vertex(ring, i)) directions.insert(directions.begin(), {e_in, {-e_out.x, -e_out.y}});
      }
      // On a convex part, the diagonals to every vertex but the neighbours (a hexagon into two
      // quadrilaterals, a pentagon into a quadrilateral and a triangle).
      if (convex) {
        for (size_t j = 2; j + 1 < m; ++j) {
          const Point2 w = ring[(i + j) % m];
          directions.push_back({w.x - v.x, w.y - v.y});
        }
      }
      // Each direction once (as a ray for partial cuts, as a line for full ones), compared as unit
      // vectors.
      partial.clear();
      full.clear();
      partial_unit.clear();
      full_unit.clear();
      for (const Point2& d : directions) {
        const Point2 u = unit(d);
        bool seen = false;
        for (const Point2& q : partial_unit) seen = seen || (std::fabs(cross(q, u)) < 1e-9 && dot(q, u) > 0.0);
        if (!seen && points_inside(to_p, e_out, u)) {
          partial.push_back(d);
          partial_unit.push_back(u);
        }
        bool seen_line = false;
        for (const Point2& q : full_unit) seen_line = seen_line || std::fabs(cross(q, u)) < 1e-9;
        if (!seen_line && !convex) {  // on a convex part a full cut is a partial one
          full.push_back(d);
          full_unit.push_back(u);
        }
      }
      for (const Point2& d : partial) actions.push_back({RegionAction::Kind::Cut, {CutKind::Partial, v, d}});
      for (const Point2& d : full) actions.push_back({RegionAction::Kind::Cut, {CutKind::Full, v, d}});
      // From the midpoint of the edge v-n, the ray along its inward normal (a partial cut from a point
      // on an edge: a trapezoid into two quadrilaterals).
      const Point2 mid{0.5 * (v.x + n.x), 0.5 * (v.y + n.y)};
      actions.push_back({RegionAction::Kind::Cut, {CutKind::Partial, mid, {-e_out.y, e_out.x}}});
    }
  }
  if (part.holes().size() >= 2) hole_separating_cuts(part, smooth_holes, ax, ay, &actions);
  if (template_applies(part) && !is_block(part) && !fillet_needs_cuts(part)) {
    actions.push_back({RegionAction::Kind::Template, {}});
  }
  return actions;
}

RegionAction progress_action(const Region& part, const BlockRules& rules) {
  // The actions that make progress in principle, most certain first; the first one that does (its
  // pieces computed) is the answer. Rounding can defeat one (a cut refused for leaving touching
  // loops), never all of them.
  std::vector<RegionAction> tries;
  for (const Ring& hole : part.holes()) {
    // The line through a hole's vertex along the bisector of its angle runs through the hole and the
    // part on both sides, along no edge.
    const size_t m = hole.size();
    for (size_t i = 0; i < m; ++i) {
      const Point2 p = hole[(i + m - 1) % m], v = hole[i], n = hole[(i + 1) % m];
      const Point2 a = unit({p.x - v.x, p.y - v.y}), b = unit({n.x - v.x, n.y - v.y});
      Point2 d{a.x + b.x, a.y + b.y};
      if (!(std::hypot(d.x, d.y) > 1e-9)) d = {-a.y, a.x};
      tries.push_back({RegionAction::Kind::Cut, {CutKind::Full, v, d}});
    }
  }
  const Ring& ring = part.outer();
  const size_t m = ring.size();
  // At an arc's open end, the cut square to the boundary there (it closes that end).
  auto square_at_open_ends = [&](const ArcRun& run) {
    if (run.open_before) {
      const Point2 p = ring[(run.first + m - 1) % m], v = ring[run.first];
      tries.push_back({RegionAction::Kind::Cut, {CutKind::Partial, v, {-(v.y - p.y), v.x - p.x}}});
    }
    if (run.open_after) {
      const Point2 v = ring[run.last], n = ring[(run.last + 1) % m];
      tries.push_back({RegionAction::Kind::Cut, {CutKind::Partial, v, {-(n.y - v.y), n.x - v.x}}});
    }
  };
  if (part.holes().empty()) {
    // At a concave arc's open ends, the square cuts; across a long closed one, the cut square to it at
    // its middle vertex.
    for (const ArcRun& run : concave_runs(ring, rules)) {
      square_at_open_ends(run);
      if (!run.open_before && !run.open_after && run.turn > kClosedRunLimit) {
        const size_t count = (run.last + m - run.first) % m + 1, i = (run.first + count / 2) % m;
        const Point2 p = ring[(i + m - 1) % m], n = ring[(i + 1) % m];
        tries.push_back({RegionAction::Kind::Cut, {CutKind::Partial, ring[i], {-(n.y - p.y), n.x - p.x}}});
      }
    }
    // The reflex corners' edge extensions, then the reflex side vertices' (rounding's, and a concave
    // arc's samples: their cuts run along it).
    for (const bool side : {false, true}) {
      for (size_t i = 0; i < m; ++i) {
        if (!is_reflex_vertex(ring, i) || is_side_vertex(ring, i, rules) != side) continue;
        const Point2 p = ring[(i + m - 1) % m], v = ring[i], n = ring[(i + 1) % m];
        tries.push_back({RegionAction::Kind::Cut, {CutKind::Partial, v, {v.x - p.x, v.y - p.y}}});
        tries.push_back({RegionAction::Kind::Cut, {CutKind::Partial, v, {v.x - n.x, v.y - n.y}}});
      }
    }
    // At a long convex arc's open end, the cut square to the boundary (block.h convex_runs).
    for (const ArcRun& run : convex_runs(ring, rules)) {
      if (open_fillet(run)) square_at_open_ends(run);
    }
    if (tries.empty()) {
      std::vector<size_t> corners;
      for (size_t i = 0; i < m; ++i) {
        if (!is_side_vertex(ring, i, rules)) corners.push_back(i);
      }
      if (corners.size() >= 5) {
        for (size_t k = 0; k < corners.size(); ++k) {
          const Point2 a = ring[corners[k]], b = ring[corners[(k + corners.size() / 2) % corners.size()]];
          tries.push_back({RegionAction::Kind::Cut, {CutKind::Partial, a, {b.x - a.x, b.y - a.y}}});
        }
      }
    }
  }
  for (const RegionAction& action : tries) {
    if (makes_progress(part, cut_region(part, action.cut).pieces, rules)) return action;
  }
  if (template_applies(part)) return {RegionAction::Kind::Template, {}};
  // Last resort: a cut that does not keep clear of the vertices (region_cut.h).
  for (RegionAction action : tries) {
    action.cut.forced = true;
    if (makes_progress(part, cut_region(part, action.cut).pieces, rules)) return action;
  }
  return tries.empty() ? RegionAction{RegionAction::Kind::Template, {}} : tries.front();
}

}  // namespace autoblock
