#include "core/region/block.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

namespace autoblock {
namespace {

constexpr double kDegree = M_PI / 180.0;
// The O-grid template (block.h): the corners' least angle (and 180 less it, the largest); the room
// between the hole and every side is kOgridClearance (block.h).
constexpr double kOgridMinCorner = 60.0;
constexpr double kOgridSideTurn = 60.0;  // the most a side may bend along an arc, degrees in all
constexpr double kOgridCurvedPatch = 0.45;  // the least Coons patch Jacobian of its pieces with curved sides
constexpr double kOgridCurvedBeyond = 1.5;  // how far beyond the hole its box may lie with curved sides, in radii
// A tight cell's O-grid (block.h): the least and the most room between the hole and a side, in radii;
// the least sine of a corner's angles either side of the line to the hole's centre; the least Coons
// patch Jacobian of its pieces.
constexpr double kOgridTightClearance = 0.1;
constexpr double kOgridSnugClearance = 1.0;
constexpr double kOgridTightSine = 0.62;
constexpr double kOgridTightPatch = 0.45;

// The centre of the largest circle inside a convex polygon (counter-clockwise): the linear program
// max r subject to dist_k(p) >= r for every side's line, solved at its vertices (three sides' lines
// at equal distance; a handful of sides, so every triple is tried). A degenerate polygon gives the
// mean of its vertices.
Point2 largest_inscribed_centre(const std::vector<Point2>& polygon) {
  const size_t m = polygon.size();
  struct Line {
    double nx, ny, d;  // inward unit normal; dist(p) = n . p - d
  };
  std::vector<Line> lines;
  for (size_t k = 0; k < m; ++k) {
    const Point2 a = polygon[k], b = polygon[(k + 1) % m];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    if (len <= 0.0) continue;
    const double nx = -(b.y - a.y) / len, ny = (b.x - a.x) / len;
    lines.push_back({nx, ny, nx * a.x + ny * a.y});
  }
  Point2 mean{0.0, 0.0};
  for (const Point2& p : polygon) mean = Point2{mean.x + p.x / static_cast<double>(m), mean.y + p.y / static_cast<double>(m)};
  double extent = 0.0;
  for (const Point2& p : polygon) extent = std::max(extent, std::hypot(p.x - mean.x, p.y - mean.y));
  Point2 best = mean;
  double best_r = 0.0;
  const size_t n = lines.size();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      for (size_t l = j + 1; l < n; ++l) {
        // n_k . p - r = d_k for k = i, j, l (Cramer's rule on the 3 x 3 system in x, y, r).
        const Line& a = lines[i];
        const Line& b = lines[j];
        const Line& c = lines[l];
        auto det3 = [](double a1, double a2, double a3, double b1, double b2, double b3, double c1, double c2, double c3) {
          return a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1);
        };
        const double det = det3(a.nx, a.ny, -1.0, b.nx, b.ny, -1.0, c.nx, c.ny, -1.0);
        if (std::fabs(det) < 1e-12) continue;
        const double x = det3(a.d, a.ny, -1.0, b.d, b.ny, -1.0, c.d, c.ny, -1.0) / det;
        const double y = det3(a.nx, a.d, -1.0, b.nx, b.d, -1.0, c.nx, c.d, -1.0) / det;
        const double r = det3(a.nx, a.ny, a.d, b.nx, b.ny, b.d, c.nx, c.ny, c.d) / det;
        if (!(r > best_r)) continue;
        bool inside = true;
        for (const Line& e : lines) inside = inside && e.nx * x + e.ny * y - e.d >= r - 1e-9 * extent;
        if (inside) {
          best = Point2{x, y};
          best_r = r;
        }
      }
    }
  }
  return best;
}

}  // namespace

bool is_side_vertex(const Ring& ring, size_t i, const BlockRules& rules) {
  // |interior angle - 180| <= tolerance is the turn from the incoming to the outgoing edge within
  // the tolerance: a forward turn (positive dot product) whose |cross| <= tan(tolerance) dot (no
  // trigonometry on this hot path).
  const double tolerance = rules.flat_tolerance_degrees;
  if (!(tolerance < 90.0)) return std::fabs(interior_angle(ring, i) - M_PI) <= tolerance * kDegree;
  static const double default_tan = std::tan(BlockRules{}.flat_tolerance_degrees * kDegree);
  const double tan_tolerance = tolerance == BlockRules{}.flat_tolerance_degrees ? default_tan : std::tan(tolerance * kDegree);
  const size_t n = ring.size();
  const Point2 p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
  const double ax = v.x - p.x, ay = v.y - p.y, bx = q.x - v.x, by = q.y - v.y;
  const double dot = ax * bx + ay * by, cross = ax * by - ay * bx;
  if (!(dot > 0.0)) return false;
  return std::fabs(cross) <= tan_tolerance * dot;
}

VertexShape vertex_shape(const Ring& ring, size_t i, const BlockRules& rules) {
  const double tolerance = rules.flat_tolerance_degrees;
  if (!(tolerance < 90.0)) return {is_side_vertex(ring, i, rules), is_reflex_vertex(ring, i)};
  static const double default_tan = std::tan(BlockRules{}.flat_tolerance_degrees * kDegree);
  const double tan_tolerance = tolerance == BlockRules{}.flat_tolerance_degrees ? default_tan : std::tan(tolerance * kDegree);
  const size_t n = ring.size();
  const Point2 p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
  // The products of is_reflex_vertex (from v to its neighbours); is_side_vertex's (along the edges)
  // are the same cross product and the dot product negated, exactly.
  const double ax = q.x - v.x, ay = q.y - v.y, bx = p.x - v.x, by = p.y - v.y;
  const double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
  return {-dot > 0.0 && std::fabs(cross) <= tan_tolerance * -dot, cross < 0.0 || (cross == 0.0 && dot >= 0.0)};
}

namespace {

// Inputs: ring; corners, its four corners (counter-clockwise). Output: the least scaled Jacobian at
//         the corners of the cells of an 8 x 8 grid of the Coons patch of its four sides (each a
//         polyline parametrised by length); <= 0 where the patch folds. A block whose sides bend much
//         (arcs, circular_arc.h: a convex fillet facing a hole's concave arc, a rounded corner in the
//         middle of a side facing a straight one) can fold or squeeze its cells so; its mapped mesh
//         would have inverted or flattened quads.
double coons_patch_jacobian(const Ring& ring, const std::array<int, 4>& corners) {
  const size_t n = ring.size();
  // Side k's points from corner k to corner k + 1, and their lengths along it.
  std::array<std::vector<Point2>, 4> sides;
  std::array<std::vector<double>, 4> at;
  for (size_t k = 0; k < 4; ++k) {
    for (size_t i = static_cast<size_t>(corners[k]);; i = (i + 1) % n) {
      const Point2 p = ring[i];
      at[k].push_back(sides[k].empty() ? 0.0 : at[k].back() + std::hypot(p.x - sides[k].back().x, p.y - sides[k].back().y));
      sides[k].push_back(p);
      if (i == static_cast<size_t>(corners[(k + 1) % 4])) break;
    }
  }
  auto point = [&](size_t k, double t) {  // side k at the fraction t of its length
    const std::vector<double>& a = at[k];
    const double s = t * a.back();
    size_t j = 1;
    while (j + 1 < a.size() && a[j] < s) ++j;
    const double e = a[j] - a[j - 1], f = e > 0.0 ? (s - a[j - 1]) / e : 0.0;
    const Point2 p = sides[k][j - 1], q = sides[k][j];
    return Point2{p.x + f * (q.x - p.x), p.y + f * (q.y - p.y)};
  };
  constexpr int m = 8;
  std::array<std::array<Point2, m + 1>, m + 1> grid;
  const Point2 c0 = sides[0].front(), c1 = sides[1].front(), c2 = sides[2].front(), c3 = sides[3].front();
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= m; ++j) {
      const double u = static_cast<double>(i) / m, v = static_cast<double>(j) / m;
      const Point2 b = point(0, u), r = point(1, v), t = point(2, 1.0 - u), l = point(3, 1.0 - v);
      grid[static_cast<size_t>(i)][static_cast<size_t>(j)] =
          Point2{(1 - v) * b.x + v * t.x + (1 - u) * l.x + u * r.x -
                     ((1 - u) * (1 - v) * c0.x + u * (1 - v) * c1.x + u * v * c2.x + (1 - u) * v * c3.x),
                 (1 - v) * b.y + v * t.y + (1 - u) * l.y + u * r.y -
                     ((1 - u) * (1 - v) * c0.y + u * (1 - v) * c1.y + u * v * c2.y + (1 - u) * v * c3.y)};
    }
  }
  double least = 1.0;
  for (size_t i = 0; i < m; ++i) {
    for (size_t j = 0; j < m; ++j) {
      const std::array<Point2, 4> q{grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]};
      for (size_t k = 0; k < 4; ++k) {
        const Point2 v = q[k], next = q[(k + 1) % 4], prev = q[(k + 3) % 4];
        const double ax = next.x - v.x, ay = next.y - v.y, bx = prev.x - v.x, by = prev.y - v.y;
        const double cross = ax * by - ay * bx, length = std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
        if (!(cross > 0.0) || !(length > 0.0)) return 0.0;
        least = std::min(least, cross / length);
      }
    }
  }
  return least;
}

// Inputs: ring. Output: the sum over its vertices of the absolute turn, in radians, at those within
//         the flat tolerance (its sides' bending).
double side_bending(const Ring& ring, const BlockRules& rules) {
  double bending = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) {
    if (is_side_vertex(ring, i, rules)) bending += std::fabs(M_PI - interior_angle(ring, i));
  }
  return bending;
}

// Blocks whose sides bend more than this in total are checked for folds and squeezed cells
// (coons_patch_jacobian): the least scaled Jacobian of the patch's cells must be at least this
// fraction of the sine of the rules' least corner.
constexpr double kCheckedBendingDegrees = 30.0;
constexpr double kPatchJacobianFraction = 0.5;

}  // namespace

std::optional<std::array<int, 4>> block_corners(const Region& region, const BlockRules& rules) {
  if (region.is_empty() || !region.holes().empty()) return std::nullopt;
  const Ring& ring = region.outer();
  std::array<int, 4> corners{};
  int count = 0;
  bool concave_side = false;
  int convex_side = 0;
  // Four corners first (side vertices by cross and dot products), then their angles.
  for (size_t i = 0; i < ring.size(); ++i) {
    const VertexShape shape = vertex_shape(ring, i, rules);
    if (shape.side) {
      concave_side = concave_side || shape.reflex;
      convex_side += !shape.reflex;
      continue;
    }
    if (count == 4) return std::nullopt;
    corners[static_cast<size_t>(count++)] = static_cast<int>(i);
  }
  if (count != 4) return std::nullopt;
  // A concave arc with an open end acts as a reflex corner (a step in a side, a fillet in the middle of
  // one: concave_runs). (A closed one may be a whole side: half a hole, cut through its middle.)
  if (concave_side) {
    for (const ArcRun& run : concave_runs(ring, rules)) {
      if (run.open_before || run.open_after) return std::nullopt;
    }
  }
  // So does a long convex arc with an open end (a fillet running on into straight edges): the quads
  // beside it are squeezed; cut square at its ends, it is a side of its own. (Such a run turns by more
  // than kOpenConvexLimit, at most the flat tolerance per vertex: three convex side vertices or
  // more; part_complexity looks for it only so too.)
  if (convex_side >= 3 && open_convex_run(ring, rules)) return std::nullopt;
  // Each corner's angle t within [min, max] by its cosine (t in (0, pi] once not reflex, where the
  // cosine decreases): no trigonometry per corner.
  const double cos_min = std::cos(rules.min_corner_degrees * kDegree), cos_max = std::cos(rules.max_corner_degrees * kDegree);
  const size_t n = ring.size();
  for (const int c : corners) {
    const size_t i = static_cast<size_t>(c);
    const Point2 p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
    const double ax = q.x - v.x, ay = q.y - v.y, bx = p.x - v.x, by = p.y - v.y;
    const double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
    if (cross < 0.0 || (cross == 0.0 && dot >= 0.0)) return std::nullopt;  // reflex (is_reflex_vertex)
    const double length = std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
    if (dot > cos_min * length || dot < cos_max * length) return std::nullopt;
  }
  // Straight sides (a few side vertices from rounding or T-junctions) cannot fold; bent ones can, or
  // squeeze the patch's cells: no cell corner may be much below the rules' least corner.
  if (n > 6 && side_bending(ring, rules) > kCheckedBendingDegrees * kDegree &&
      coons_patch_jacobian(ring, corners) < kPatchJacobianFraction * std::sin(rules.min_corner_degrees * kDegree)) {
    return std::nullopt;
  }
  return corners;
}

CornerAngle piece_corner_angle(const QuadPiece& piece, int k) {
  const Point2 v = piece.ring[static_cast<size_t>(piece.corners[static_cast<size_t>(k)])];
  const Point2 next = piece.ring[static_cast<size_t>(piece.corners[static_cast<size_t>((k + 1) % 4)])];
  const Point2 prev = piece.ring[static_cast<size_t>(piece.corners[static_cast<size_t>((k + 3) % 4)])];
  const double ax = next.x - v.x, ay = next.y - v.y, bx = prev.x - v.x, by = prev.y - v.y;
  const double length = std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
  if (!(length > 0.0)) return {-1.0, 1.0};
  return {(ax * by - ay * bx) / length, (ax * bx + ay * by) / length};
}

namespace {

// The runs of a loop's side vertices that turn inwards (concave) or outwards (convex); see block.h.
std::vector<ArcRun> side_runs(const Ring& ring, const BlockRules& rules, bool convex) {
  const size_t n = ring.size();
  std::vector<VertexShape> shape(n);
  size_t start = n;  // a vertex outside every run
  auto in_run = [&](size_t i) { return shape[i].side && shape[i].reflex != convex; };
  for (size_t i = 0; i < n; ++i) shape[i] = vertex_shape(ring, i, rules);
  for (size_t i = 0; i < n && start == n; ++i) {
    if (!in_run(i)) start = i;
  }
  std::vector<ArcRun> runs;
  if (start == n) return runs;
  auto length = [&](size_t i, size_t j) { return std::hypot(ring[j].x - ring[i].x, ring[j].y - ring[i].y); };
  // A convex run breaks at a long edge: from i to i + 1, more than twice the edges beside it.
  auto long_edge = [&](size_t i) {
    if (!convex) return false;
    const size_t j = (i + 1) % n;
    return length(i, j) > 2.0 * std::max(length((i + n - 1) % n, i), length(j, (j + 1) % n));
  };
  // Whether the boundary runs on smoothly for more than `reach` from vertex `from`, stepping by
  // `step` (+1 or n - 1), before a corner.
  auto open_end = [&](size_t from, size_t step, double reach) {
    double along = 0.0;
    for (size_t i = from, k = 0; k < n; ++k) {
      const size_t j = (i + step) % n;
      along += length(i, j);
      if (along > reach) return true;
      if (!shape[j].side) return false;
      i = j;
    }
    return true;
  };
  for (size_t k = 1; k <= n; ++k) {
    const size_t first = (start + k) % n;
    const size_t before = (first + n - 1) % n;
    if (!in_run(first) || (in_run(before) && !long_edge(before))) continue;
    ArcRun run;
    run.first = first;
    double chord = 0.0;
    size_t last = first;
    const double sign = convex ? -1.0 : 1.0;
    run.turn = sign * (interior_angle(ring, first) - M_PI);
    for (size_t steps = 1; steps < n && in_run((last + 1) % n) && !long_edge(last); ++steps) {
      chord = std::max(chord, length(last, (last + 1) % n));
      last = (last + 1) % n;
      run.turn += sign * (interior_angle(ring, last) - M_PI);
    }
    run.last = last;
    if (!(run.turn > rules.flat_tolerance_degrees * kDegree)) continue;
    run.open_before = open_end(first, n - 1, 1.5 * chord);
    run.open_after = open_end(last, 1, 1.5 * chord);
    runs.push_back(run);
  }
  return runs;
}

}  // namespace

std::vector<ArcRun> concave_runs(const Ring& ring, const BlockRules& rules) { return side_runs(ring, rules, false); }

std::vector<ArcRun> convex_runs(const Ring& ring, const BlockRules& rules) { return side_runs(ring, rules, true); }

bool fillet_needs_cuts(const Region& region, const BlockRules& rules) {
  if (region.is_empty()) return false;
  const Ring& ring = region.outer();
  int corners = 0;
  for (size_t i = 0; i < ring.size(); ++i) corners += !is_side_vertex(ring, i, rules);
  return corners >= 3 && open_convex_run(ring, rules);
}

bool open_convex_run(const Ring& ring, const BlockRules& rules) {
  for (const ArcRun& run : convex_runs(ring, rules)) {
    if (open_fillet(run)) return true;
  }
  return false;
}

namespace {

// Inputs: region; a spoke from an interior point to a boundary point. Output: true when the spoke,
//         up to within a hundredth of its length of the boundary point, keeps clear of every edge
//         (closed segments, exact predicates).
bool spoke_clear(const Region& region, Point2 inner, Point2 end) {
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const K::Segment_2 spoke(K::Point_2(inner.x, inner.y),
                           K::Point_2(end.x + 0.01 * (inner.x - end.x), end.y + 0.01 * (inner.y - end.y)));
  for (size_t i = 0; i < n; ++i) {
    const Point2 a = ring[i], b = ring[(i + 1) % n];
    if (CGAL::do_intersect(spoke, K::Segment_2(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y)))) return false;
  }
  return true;
}

// Inputs: region, without holes; pieces, its usual template's. Output: true when the spokes (a
//         piece's corners 1-2-3: foot, centre, foot) keep clear of the boundary but at their feet, and
//         every piece turns counter-clockwise: a concave run can bulge over the centre of the polygon
//         of corners.
bool template_spokes_clear(const Region& region, const std::vector<QuadPiece>& pieces) {
  for (const QuadPiece& piece : pieces) {
    if (signed_area(piece.ring) <= 0.0) return false;
    const Point2 centre = piece.ring[static_cast<size_t>(piece.corners[2])];
    const Point2 foot = piece.ring[static_cast<size_t>(piece.corners[1])];
    if (!spoke_clear(region, centre, foot)) return false;
  }
  return true;
}

}  // namespace

bool template_applies(const Region& region) {
  if (region.is_convex()) return true;
  if (region.is_empty()) return false;
  if (!region.holes().empty()) return ogrid_template(region);
  // Convex but for side vertices turned a little the other way (within the flat tolerance; rounding
  // to the lattice makes them): they lie on the template's sides, as on a block's. Together they may
  // turn inwards by no more than the flat tolerance: a concave arc (circular_arc.h) is a chain of such
  // vertices, and a part with one is far from convex, unless the arc is one whole side (a concave run
  // closed at both ends) of at most kClosedRunLimit, and the template's spokes keep clear of it.
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  const BlockRules rules;
  double inwards = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!is_reflex_vertex(ring, i)) continue;
    if (!is_side_vertex(ring, i, rules)) return false;
    inwards += interior_angle(ring, i) - M_PI;
  }
  if (inwards <= rules.flat_tolerance_degrees * kDegree) return true;
  const std::vector<ArcRun> runs = concave_runs(ring, rules);
  if (runs.size() != 1 || runs[0].open_before || runs[0].open_after || runs[0].turn > kClosedRunLimit) return false;
  if (inwards > runs[0].turn + rules.flat_tolerance_degrees * kDegree) return false;
  return template_spokes_clear(region, template_pieces(region, rules));
}

namespace {

// The template's corners: the ring's corners (side vertices lie on the template's sides). When fewer
// than three are corners (a part with a long smooth side: arcs, circular_arc.h; the smooth template
// did not apply), the vertices farthest from those chosen are added until there are three: with
// none, the two farthest apart; then the vertex farthest from the line through the first two.
// All vertices when the ring has only three.
std::vector<size_t> template_corners(const Ring& ring, const BlockRules& rules) {
  std::vector<size_t> corners;
  for (size_t i = 0; i < ring.size(); ++i) {
    if (!is_side_vertex(ring, i, rules)) corners.push_back(i);
  }
  if (corners.size() >= 3) return corners;
  if (ring.size() <= 3) {
    corners.clear();
    for (size_t i = 0; i < ring.size(); ++i) corners.push_back(i);
    return corners;
  }
  auto distance = [&](size_t i, size_t j) { return std::hypot(ring[i].x - ring[j].x, ring[i].y - ring[j].y); };
  if (corners.empty()) {
    size_t a = 0, b = 1;
    for (size_t i = 0; i < ring.size(); ++i) {
      for (size_t j = i + 1; j < ring.size(); ++j) {
        if (distance(i, j) > distance(a, b)) a = i, b = j;
      }
    }
    corners = {a, b};
  } else if (corners.size() == 1) {
    size_t b = corners[0] == 0 ? 1 : 0;
    for (size_t i = 0; i < ring.size(); ++i) {
      if (distance(corners[0], i) > distance(corners[0], b)) b = i;
    }
    corners.push_back(b);
  }
  const Point2 a = ring[corners[0]], b = ring[corners[1]];
  size_t apex = corners[0];
  double farthest = -1.0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const double d = std::fabs((b.x - a.x) * (ring[i].y - a.y) - (b.y - a.y) * (ring[i].x - a.x));
    if (i != corners[0] && i != corners[1] && d > farthest) farthest = d, apex = i;
  }
  corners.push_back(apex);
  std::sort(corners.begin(), corners.end());
  return corners;
}

// The smooth part's template (fewer than three corners: a disk, a rounded rectangle, a D): four
// boundary vertices, those nearest the corners of the part's minimum-area rectangle, in the ring's
// order; nothing when they are not four distinct vertices.
std::vector<size_t> smooth_template_corners(const Region& region) {
  const Ring& ring = region.outer();
  const OrientedRectangle box = min_area_rectangle(region);
  const Point2 u = box.axis, v{-box.axis.y, box.axis.x};
  std::vector<size_t> picked;
  for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, std::pair{1.0, -1.0}, std::pair{1.0, 1.0}, std::pair{-1.0, 1.0}}) {
    const Point2 corner{box.center.x + 0.5 * (su * box.width * u.x + sv * box.height * v.x),
                        box.center.y + 0.5 * (su * box.width * u.y + sv * box.height * v.y)};
    size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < ring.size(); ++i) {
      const double d = std::hypot(ring[i].x - corner.x, ring[i].y - corner.y);
      if (d < best_d) best_d = d, best = i;
    }
    picked.push_back(best);
  }
  std::sort(picked.begin(), picked.end());
  if (std::adjacent_find(picked.begin(), picked.end()) != picked.end()) return {};
  return picked;
}


// True when every piece's quadrilateral of corners turns counter-clockwise with every angle within
// [20, 160] degrees: the smooth template of a long or thin part can fold.
bool pieces_well_shaped(const std::vector<QuadPiece>& pieces) {
  const double cos_limit = std::cos(20.0 * M_PI / 180.0);
  for (const QuadPiece& piece : pieces) {
    for (int k = 0; k < 4; ++k) {
      const CornerAngle a = piece_corner_angle(piece, k);
      if (a.sine <= 0.0 || std::fabs(a.cosine) > cos_limit) return false;
    }
  }
  return true;
}

// The smooth template's pieces (see block.h) from its four boundary vertices v (smooth_template_corners).
// inset = 0: the inner quadrilateral's corners halfway from v to the centroid. inset > 0 (a long part,
// whose halfway corners would fold its side pieces): each of v moved into the minimum-area rectangle
// shrunk by inset on every side (box: that rectangle), so the inner corners keep their distance from
// the ends as from the sides.
std::vector<QuadPiece> smooth_template_pieces(const Region& region, const std::vector<size_t>& v, double inset = 0.0,
                                              const OrientedRectangle* box = nullptr) {
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  const Point2 c = region.centroid();
  std::array<Point2, 4> inner;
  for (size_t k = 0; k < 4; ++k) {
    Point2 p{0.5 * (c.x + ring[v[k]].x), 0.5 * (c.y + ring[v[k]].y)};
    if (inset > 0.0 && box) {
      const Point2 u = box->axis, w{-u.y, u.x}, d{ring[v[k]].x - box->center.x, ring[v[k]].y - box->center.y};
      const double a = std::clamp(d.x * u.x + d.y * u.y, -(0.5 * box->width - inset), 0.5 * box->width - inset);
      const double b = std::clamp(d.x * w.x + d.y * w.y, -(0.5 * box->height - inset), 0.5 * box->height - inset);
      p = Point2{box->center.x + a * u.x + b * w.x, box->center.y + a * u.y + b * w.y};
    }
    inner[k] = Point2{snap_to_lattice(p.x, region.quantum()), snap_to_lattice(p.y, region.quantum())};
  }
  std::vector<QuadPiece> pieces;
  for (size_t k = 0; k < 4; ++k) {
    QuadPiece piece;
    for (size_t i = v[k]; i != v[(k + 1) % 4]; i = (i + 1) % n) piece.ring.push_back(ring[i]);
    piece.corners = {0, static_cast<int>(piece.ring.size()), static_cast<int>(piece.ring.size()) + 1,
                     static_cast<int>(piece.ring.size()) + 2};
    piece.ring.push_back(ring[v[(k + 1) % 4]]);
    piece.ring.push_back(inner[(k + 1) % 4]);
    piece.ring.push_back(inner[k]);
    pieces.push_back(std::move(piece));
  }
  QuadPiece middle;
  middle.ring = Ring(inner.begin(), inner.end());
  middle.corners = {0, 1, 2, 3};
  pieces.push_back(std::move(middle));
  return pieces;
}

// The O-grid template's pieces (see block.h) when it applies, else nothing: made once, both to decide
// and to use.
double pieces_patch_jacobian(const std::vector<QuadPiece>& pieces);  // below

std::optional<std::vector<QuadPiece>> applicable_ogrid_template(const Region& region, const BlockRules& rules) {
  if (region.holes().size() != 1) return std::nullopt;
  const double q = region.quantum();
  // A smooth convex hole (a circle, a slot): every vertex a side vertex, turning 360 degrees in all
  // (within the flat tolerance: a tangent join may turn slightly the other way).
  const Ring& hole = region.holes()[0];
  const size_t m = hole.size();
  if (m < 8) return std::nullopt;
  double turning = 0.0;
  for (size_t i = 0; i < m; ++i) {
    if (!is_side_vertex(hole, i, BlockRules{})) return std::nullopt;
    turning += std::fabs(interior_angle(hole, i) - M_PI);
  }
  if (turning > 2.0 * M_PI + BlockRules{}.flat_tolerance_degrees * kDegree) return std::nullopt;
  const Point2 c = ring_centroid(hole);
  // Four convex corners within [60, 120] degrees and straight sides between them.
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  std::vector<size_t> corner;
  for (size_t i = 0; i < n; ++i) {
    const VertexShape shape = vertex_shape(ring, i, rules);
    if (shape.side) continue;
    if (shape.reflex || corner.size() == 4) return std::nullopt;
    const double t = interior_angle(ring, i);
    if (t < kOgridMinCorner * kDegree || t > M_PI - kOgridMinCorner * kDegree) return std::nullopt;
    corner.push_back(i);
  }
  if (corner.size() != 4) return std::nullopt;
  // Side k runs from corner k to corner k + 1: its chord's unit direction, inward normal, and the
  // hole centre's distance from the side (from its nearest vertex: a side along an arc, a bore's, may
  // bulge towards the hole). A side is straight (its side vertices, T-junctions, on its chord) or
  // bends along an arc (an annular sector of a flange) by at most kOgridSideTurn in all, its vertices
  // in order along its chord.
  std::array<Point2, 4> e, normal;
  std::array<double, 4> length{}, d{}, reach{};
  std::array<bool, 4> curved{};
  for (size_t k = 0; k < 4; ++k) {
    const Point2 a = ring[corner[k]], b = ring[corner[(k + 1) % 4]];
    length[k] = std::hypot(b.x - a.x, b.y - a.y);
    e[k] = {(b.x - a.x) / length[k], (b.y - a.y) / length[k]};
    normal[k] = {-e[k].y, e[k].x};
    d[k] = normal[k].x * (c.x - a.x) + normal[k].y * (c.y - a.y);
    double turn = 0.0, along = -std::numeric_limits<double>::infinity(), nearest = d[k];
    for (size_t i = corner[k]; i != corner[(k + 1) % 4]; i = (i + 1) % n) {
      const Point2 v = ring[i];
      curved[k] = curved[k] || std::fabs(normal[k].x * (v.x - a.x) + normal[k].y * (v.y - a.y)) > 2.0 * q;
      nearest = std::min(nearest, normal[k].x * (c.x - v.x) + normal[k].y * (c.y - v.y));
      const double t = e[k].x * (v.x - a.x) + e[k].y * (v.y - a.y);
      if (t <= along) return std::nullopt;
      along = t;
      if (i != corner[k]) turn += std::fabs(interior_angle(ring, i) - M_PI);
    }
    if (turn > kOgridSideTurn * kDegree) return std::nullopt;
    if (curved[k]) d[k] = nearest;
    // How far the hole reaches from its centre towards side k.
    for (const Point2& v : hole) reach[k] = std::max(reach[k], -(normal[k].x * (v.x - c.x) + normal[k].y * (v.y - c.y)));
  }
  // Curved sides: an annular sector's two, or one over a straight side (a cell that a chord between
  // two bolt circles cut off from the bore or the rim, divide_sector). (One curved side was refused
  // while the search cut such cells itself, next to a rim: two flanges of two bolt circles fell from
  // 0.64 and 0.75 to 0.33 and 0.48; with divide_sector's chords, 30 flanges 0.70 -> 0.75.)
  const bool any_curved = curved[0] || curved[1] || curved[2] || curved[3];
  // Room on every side: the gap to the side at least half the hole's smallest reach (its radius) and
  // 64 quanta, for a ring and a strip beyond it.
  const double radius = *std::min_element(reach.begin(), reach.end());
  bool roomy = true, snug = true;
  for (size_t k = 0; k < 4; ++k) {
    if (!(d[k] - reach[k] >= std::max(kOgridTightClearance * radius, 64.0 * q))) return std::nullopt;
    roomy = roomy && d[k] - reach[k] >= std::max(kOgridClearance * radius, 64.0 * q);
    snug = snug && d[k] - reach[k] <= kOgridSnugClearance * radius;
  }
  if (!roomy && !snug) return std::nullopt;
  // The hole's vertex nearest each of the points given (a box corner or a part's corner), where a
  // spoke from there meets the hole about square.
  auto nearest_on_hole = [&](const std::array<Point2, 4>& from) {
    std::array<size_t, 4> h{};
    for (size_t k = 0; k < 4; ++k) {
      double best = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < m; ++j) {
        const double dist = std::hypot(hole[j].x - from[k].x, hole[j].y - from[k].y);
        if (dist < best) best = dist, h[k] = j;
      }
    }
    return h;
  };
  if (!roomy) {
    // A tight cell: the part's sides are the box. Four pieces, each a side of the part, the spokes from
    // its corners and the hole between them (the hole runs clockwise, the part counter-clockwise).
    std::array<Point2, 4> corner_at;
    for (size_t k = 0; k < 4; ++k) corner_at[k] = ring[corner[k]];
    // Each corner split by the line to the hole's centre (the spoke's direction, whatever the hole's
    // polygon) into angles whose sines are kOgridTightSine at least.
    for (size_t k = 0; k < 4; ++k) {
      const Point2 a = corner_at[k], s{c.x - a.x, c.y - a.y};
      for (const Point2 b : {corner_at[(k + 1) % 4], corner_at[(k + 3) % 4]}) {
        const Point2 side{b.x - a.x, b.y - a.y};
        const double sine = std::fabs(s.x * side.y - s.y * side.x) / (std::hypot(s.x, s.y) * std::hypot(side.x, side.y));
        if (!(sine >= kOgridTightSine)) return std::nullopt;
      }
    }
    const std::array<size_t, 4> h = nearest_on_hole(corner_at);
    std::vector<QuadPiece> pieces;
    for (size_t k = 0; k < 4; ++k) {
      Ring loop;
      for (size_t i = corner[k]; i != corner[(k + 1) % 4]; i = (i + 1) % n) loop.push_back(ring[i]);
      const int at_corner = static_cast<int>(loop.size());
      loop.push_back(ring[corner[(k + 1) % 4]]);
      for (size_t j = h[(k + 1) % 4]; j != h[k]; j = (j + 1) % m) loop.push_back(hole[j]);
      const int at_last = static_cast<int>(loop.size());
      loop.push_back(hole[h[k]]);
      if (at_last < at_corner + 2) return std::nullopt;  // two corners aimed at one hole vertex
      pieces.push_back(QuadPiece{std::move(loop), {0, at_corner, at_corner + 1, at_last}});
    }
    if (!pieces_well_shaped(pieces) || pieces_patch_jacobian(pieces) < kOgridTightPatch) return std::nullopt;
    return pieces;
  }
  // The box: its side k parallel to side k, halfway from the hole to the side (the ring and the strip
  // beyond equally thick) but at most a radius beyond the hole.
  std::array<double, 4> offset{};
  // (In an annular sector up to kOgridCurvedBeyond radii: an eight-bolt flange's sectors, 45 degrees
  // wide, 0.867 with the box one radius beyond its holes, 0.947 with one and a half.)
  const double beyond = any_curved ? kOgridCurvedBeyond : 1.0;
  for (size_t k = 0; k < 4; ++k) offset[k] = std::min(0.5 * (reach[k] + d[k]), reach[k] + beyond * radius);
  std::array<Point2, 4> box, foot_on_side, foot_on_previous, strip_on_side, strip_on_previous;
  bool strips = any_curved;
  for (size_t k = 0; k < 4; ++k) {
    // Box corner k: on box lines k - 1 and k, normal . (x - c) = -offset.
    const size_t p = (k + 3) % 4;
    const double a11 = normal[p].x, a12 = normal[p].y, a21 = normal[k].x, a22 = normal[k].y;
    const double det = a11 * a22 - a12 * a21;
    if (!(std::fabs(det) > 1e-9)) return std::nullopt;
    const double b1 = -offset[p], b2 = -offset[k];
    const Point2 x{c.x + (b1 * a22 - a12 * b2) / det, c.y + (a11 * b2 - b1 * a21) / det};
    box[k] = {snap_to_lattice(x.x, q), snap_to_lattice(x.y, q)};
    foot_on_side[k] = {x.x - (d[k] - offset[k]) * normal[k].x, x.y - (d[k] - offset[k]) * normal[k].y};
    foot_on_previous[k] = {x.x - (d[p] - offset[p]) * normal[p].x, x.y - (d[p] - offset[p]) * normal[p].y};
    if (!strips) continue;
    // An annular sector's other feet: where the box line through the corner meets the side's chord
    // (along box line k - 1 to side k, along box line k to side k - 1), so that the strips between
    // the box and the radial sides keep their width.
    const Point2 ak = ring[corner[k]], ap = ring[corner[p]];
    const double across_k = normal[k].x * e[p].x + normal[k].y * e[p].y, across_p = normal[p].x * e[k].x + normal[p].y * e[k].y;
    strips = std::fabs(across_k) > 0.1 && std::fabs(across_p) > 0.1;
    if (!strips) continue;
    const double s_k = -(normal[k].x * (x.x - ak.x) + normal[k].y * (x.y - ak.y)) / across_k;
    const double s_p = -(normal[p].x * (x.x - ap.x) + normal[p].y * (x.y - ap.y)) / across_p;
    strip_on_side[k] = {x.x + s_k * e[p].x, x.y + s_k * e[p].y};
    strip_on_previous[k] = {x.x + s_p * e[k].x, x.y + s_p * e[k].y};
  }
  // The feet must fall inside their sides, in order, clear of the corners. A deep, narrow sector's
  // perpendicular feet fall outside its bore's side (the radial sides converge on it): there the
  // feet along the box lines are taken (a wide sector's box lines cross before the bore's side).
  // A point's position along side k's chord, from corner k.
  auto along_side = [&](size_t k, Point2 v) {
    const Point2 a = ring[corner[k]];
    return e[k].x * (v.x - a.x) + e[k].y * (v.y - a.y);
  };
  auto feet_fit = [&](const std::array<Point2, 4>& on_side, const std::array<Point2, 4>& on_previous) {
    for (size_t k = 0; k < 4; ++k) {
      const double t1 = along_side(k, on_side[k]), t2 = along_side(k, on_previous[(k + 1) % 4]);
      if (!(t1 > 32.0 * q && t2 - t1 > 32.0 * q && length[k] - t2 > 32.0 * q)) return false;
    }
    return true;
  };
  if (!feet_fit(foot_on_side, foot_on_previous)) {
    if (!strips || !feet_fit(strip_on_side, strip_on_previous)) return std::nullopt;
    foot_on_side = strip_on_side;
    foot_on_previous = strip_on_previous;
  }
  // Side k's vertices from corner k up to corner k + 1 (exclusive) with the two feet in place: a
  // side vertex within 2 quanta of a foot is the foot.
  struct SideSplit {
    std::vector<Point2> before, between, after;  // corner k .. foot 1, foot 1 .. foot 2, foot 2 .. corner k + 1
    Point2 first, second;
  };
  std::array<SideSplit, 4> split;
  for (size_t k = 0; k < 4; ++k) {
    const Point2 a = ring[corner[k]];
    auto along = [&](Point2 v) { return along_side(k, v); };
    const double t1 = along(foot_on_side[k]), t2 = along(foot_on_previous[(k + 1) % 4]);  // inside: feet_fit
    // The side's point at a position along its chord: on the chord, or on a curved side's polygon.
    auto at = [&](double t) {
      Point2 p{a.x + t * e[k].x, a.y + t * e[k].y};
      if (curved[k]) {
        for (size_t i = corner[k]; i != corner[(k + 1) % 4]; i = (i + 1) % n) {
          const Point2 u = ring[i], w = ring[(i + 1) % n];
          const double tu = along(u), tw = along(w);
          if (t >= tu && t <= tw) {
            const double f = tw > tu ? (t - tu) / (tw - tu) : 0.0;
            p = {u.x + f * (w.x - u.x), u.y + f * (w.y - u.y)};
            break;
          }
        }
      }
      return Point2{snap_to_lattice(p.x, q), snap_to_lattice(p.y, q)};
    };
    SideSplit& s = split[k];
    s.first = at(t1);
    s.second = at(t2);
    for (size_t i = corner[k]; i != corner[(k + 1) % 4]; i = (i + 1) % n) {
      const double t = along(ring[i]);
      if (std::fabs(t - t1) <= 2.0 * q) s.first = ring[i];
      else if (std::fabs(t - t2) <= 2.0 * q) s.second = ring[i];
      else if (t < t1) s.before.push_back(ring[i]);
      else if (t < t2) s.between.push_back(ring[i]);
      else s.after.push_back(ring[i]);
    }
  }
  // The hole's vertex nearest each box corner (the hole runs clockwise, the box counter-clockwise:
  // h[k + 1] comes before h[k] along the hole).
  const std::array<size_t, 4> h = nearest_on_hole(box);
  std::vector<QuadPiece> pieces;
  auto add = [&](Ring loop, std::array<int, 4> corners) { pieces.push_back(QuadPiece{std::move(loop), corners}); };
  for (size_t k = 0; k < 4; ++k) {
    const size_t p = (k + 3) % 4;
    // The corner piece: corner k, the foot on side k, the box corner, the foot on side k - 1.
    Ring loop = split[k].before;
    const int at_foot = static_cast<int>(loop.size());
    loop.push_back(split[k].first);
    loop.push_back(box[k]);
    loop.push_back(split[p].second);
    loop.insert(loop.end(), split[p].after.begin(), split[p].after.end());
    add(std::move(loop), {0, at_foot, at_foot + 1, at_foot + 2});
  }
  for (size_t k = 0; k < 4; ++k) {
    // The side piece: the two feet on side k and their box corners.
    Ring loop{split[k].first};
    loop.insert(loop.end(), split[k].between.begin(), split[k].between.end());
    const int at_second = static_cast<int>(loop.size());
    loop.push_back(split[k].second);
    loop.push_back(box[(k + 1) % 4]);
    loop.push_back(box[k]);
    add(std::move(loop), {0, at_second, at_second + 1, at_second + 2});
  }
  for (size_t k = 0; k < 4; ++k) {
    // The ring piece: box side k, then the hole from h[k + 1] back to h[k].
    Ring loop{box[k], box[(k + 1) % 4]};
    for (size_t j = h[(k + 1) % 4]; j != h[k]; j = (j + 1) % m) loop.push_back(hole[j]);
    const int at_last = static_cast<int>(loop.size());
    loop.push_back(hole[h[k]]);
    if (at_last < 3) return std::nullopt;  // two box corners aimed at one hole vertex
    add(std::move(loop), {0, 1, 2, at_last});
  }
  if (!pieces_well_shaped(pieces)) return std::nullopt;
  // Curved sides: the pieces' Coons patches must keep their cells from skewing more than a square
  // cell's do (a wide sector's box is a trapezoid, its ring pieces skewed).
  if (any_curved && pieces_patch_jacobian(pieces) < kOgridCurvedPatch) return std::nullopt;
  return pieces;
}

// The smooth template's pieces when it applies (see block.h), else nothing: made once, both to
// decide and to use.
std::optional<std::vector<QuadPiece>> applicable_smooth_template(const Region& region, const BlockRules& rules) {
  const Ring& ring = region.outer();
  if (ring.size() < 4) return std::nullopt;
  int corners = 0;
  for (size_t i = 0; i < ring.size(); ++i) corners += !is_side_vertex(ring, i, rules);
  if (corners >= 3) return std::nullopt;
  const std::vector<size_t> v = smooth_template_corners(region);
  if (v.size() != 4) return std::nullopt;
  std::vector<QuadPiece> pieces = smooth_template_pieces(region, v);
  if (pieces_well_shaped(pieces)) return pieces;
  // A long part (a finger's rounded end, a slot's half): its inner corners inset from the rectangle's
  // sides by a fraction of its shorter side instead, as far from the ends as from the sides.
  const OrientedRectangle box = min_area_rectangle(region);
  for (const double fraction : {0.25, 0.15, 0.35}) {
    pieces = smooth_template_pieces(region, v, fraction * box.shorter_side(), &box);
    if (pieces_well_shaped(pieces)) return pieces;
  }
  return std::nullopt;
}

// The least scaled Jacobian of the pieces' Coons patches (coons_patch_jacobian): what their mapped
// meshes start from, before smoothing.
double pieces_patch_jacobian(const std::vector<QuadPiece>& pieces) {
  double least = 1.0;
  for (const QuadPiece& piece : pieces) {
    if (!(signed_area(piece.ring) > 0.0)) return -1.0;
    least = std::min(least, coons_patch_jacobian(piece.ring, piece.corners));
  }
  return least;
}

// A side of a part (a polyline between two of its corners) with a point at the fraction f of its
// length: the side vertex nearest that point when one lies within kTwoCornerSnapFraction of the side's length
// (an arc's sample keeps its place on the circle), else a point inserted on the segment (a cut's
// straight side). Outputs the side with the point in it and the point's position.
constexpr double kTwoCornerSnapFraction = 0.1;
std::pair<std::vector<Point2>, size_t> side_with_station(const std::vector<Point2>& side, double f) {
  std::vector<double> at{0.0};
  for (size_t i = 1; i < side.size(); ++i) {
    at.push_back(at.back() + std::hypot(side[i].x - side[i - 1].x, side[i].y - side[i - 1].y));
  }
  const double s = f * at.back();
  size_t nearest = 0;
  for (size_t i = 1; i + 1 < side.size(); ++i) {
    if (nearest == 0 || std::fabs(at[i] - s) < std::fabs(at[nearest] - s)) nearest = i;
  }
  if (nearest != 0 && std::fabs(at[nearest] - s) <= kTwoCornerSnapFraction * at.back()) return {side, nearest};
  size_t j = 1;
  while (j + 1 < side.size() && at[j] < s) ++j;
  const double e = at[j] - at[j - 1], t = e > 0.0 ? (s - at[j - 1]) / e : 0.0;
  std::vector<Point2> out(side.begin(), side.begin() + static_cast<std::ptrdiff_t>(j));
  out.push_back(Point2{side[j - 1].x + t * (side[j].x - side[j - 1].x), side[j - 1].y + t * (side[j].y - side[j - 1].y)});
  out.insert(out.end(), side.begin() + static_cast<std::ptrdiff_t>(j), side.end());
  return {out, j};
}

// The two-corner template's pieces (block.h) for one placement: the stations at f and 1 - f of each
// side, the interior points at w of the way from the second side's station to the first side's, each
// moved by lambda of the way towards the other's.
std::optional<std::vector<QuadPiece>> two_corner_pieces(const std::vector<Point2>& s1, const std::vector<Point2>& s2,
                                                        double f, double w, double lambda, double quantum) {
  // s1 runs from corner P to corner Q, s2 from Q back to P. Stations: M1, M2 on s1 (M1 nearer P),
  // X2, X1 on s2 (X2 nearer Q).
  auto [a1, m1] = side_with_station(s1, f);
  auto [side1, m2] = side_with_station(a1, 1.0 - f);
  if (m2 <= m1) {
    // The second station snapped onto, or before, the first.
    return std::nullopt;
  }
  auto [b1, x2] = side_with_station(s2, f);
  auto [side2, x1] = side_with_station(b1, 1.0 - f);
  if (x1 <= x2 || m1 == 0 || m2 + 1 >= side1.size() || x2 == 0 || x1 + 1 >= side2.size()) return std::nullopt;
  auto lerp = [](Point2 a, Point2 b, double t) { return Point2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; };
  const Point2 base1 = lerp(side2[x1], side1[m1], w), base2 = lerp(side2[x2], side1[m2], w);
  Point2 i1 = lerp(base1, base2, lambda), i2 = lerp(base2, base1, lambda);
  i1 = Point2{snap_to_lattice(i1.x, quantum), snap_to_lattice(i1.y, quantum)};
  i2 = Point2{snap_to_lattice(i2.x, quantum), snap_to_lattice(i2.y, quantum)};
  if (i1 == i2) return std::nullopt;
  auto range = [](const std::vector<Point2>& side, size_t from, size_t to) {  // side[from..to], inclusive
    return std::vector<Point2>(side.begin() + static_cast<std::ptrdiff_t>(from), side.begin() + static_cast<std::ptrdiff_t>(to) + 1);
  };
  auto piece_of = [](std::vector<Point2> boundary, std::vector<Point2> inner, std::array<int, 4> corners) {
    QuadPiece piece;
    piece.ring = std::move(boundary);
    piece.ring.insert(piece.ring.end(), inner.begin(), inner.end());
    piece.corners = corners;
    return piece;
  };
  std::vector<QuadPiece> pieces;
  const int p_m1 = static_cast<int>(m1);
  // At P: P along s1 to M1, I1, X1 along s2 back to P (P not repeated).
  {
    std::vector<Point2> boundary = range(side1, 0, m1);
    const int at_i1 = static_cast<int>(boundary.size());
    boundary.push_back(i1);
    const std::vector<Point2> tail = range(side2, x1, side2.size() - 2);
    boundary.insert(boundary.end(), tail.begin(), tail.end());
    pieces.push_back(piece_of(boundary, {}, {0, p_m1, at_i1, at_i1 + 1}));
  }
  // Along s1: M1 to M2, I2, I1.
  {
    std::vector<Point2> boundary = range(side1, m1, m2);
    const int n = static_cast<int>(boundary.size());
    pieces.push_back(piece_of(boundary, {i2, i1}, {0, n - 1, n, n + 1}));
  }
  // At Q: M2 along s1 to Q, along s2 to X2, I2.
  {
    std::vector<Point2> boundary = range(side1, m2, side1.size() - 1);
    const int at_q = static_cast<int>(boundary.size()) - 1;
    const std::vector<Point2> more = range(side2, 1, x2);
    boundary.insert(boundary.end(), more.begin(), more.end());
    const int at_x2 = static_cast<int>(boundary.size()) - 1;
    pieces.push_back(piece_of(boundary, {i2}, {0, at_q, at_x2, at_x2 + 1}));
  }
  // Along s2: X2 to X1, I1, I2.
  {
    std::vector<Point2> boundary = range(side2, x2, x1);
    const int n = static_cast<int>(boundary.size());
    pieces.push_back(piece_of(boundary, {i1, i2}, {0, n - 1, n, n + 1}));
  }
  return pieces;
}

// Inputs: region; pieces, a two-corner template's (two_corner_pieces). Output: true when its five
//         spokes (I1 to M1, X1 and I2; I2 to M2 and X2) keep clear of the boundary.
bool two_corner_spokes_clear(const Region& region, const std::vector<QuadPiece>& pieces) {
  auto corner = [&](size_t p, size_t k) { return pieces[p].ring[static_cast<size_t>(pieces[p].corners[k])]; };
  const Point2 i1 = corner(1, 3), i2 = corner(1, 2);
  if (!spoke_clear(region, i1, corner(1, 0)) || !spoke_clear(region, i2, corner(1, 1))) return false;
  if (!spoke_clear(region, i1, corner(3, 1)) || !spoke_clear(region, i2, corner(3, 0))) return false;
  // I1 to I2: both inside once the spokes above are; the segment between them against the edges.
  return spoke_clear(region, i1, i2) && spoke_clear(region, i2, i1);
}

// The two-corner template (block.h) when it applies, with its score (pieces_patch_jacobian), else
// nothing: the best of its placements.
struct ScoredPieces {
  std::vector<QuadPiece> pieces;
  double score = -1.0;
};
std::optional<ScoredPieces> applicable_two_corner_template(const Region& region, const BlockRules& rules) {
  if (!region.holes().empty()) return std::nullopt;
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  std::vector<size_t> corners;
  for (size_t i = 0; i < n; ++i) {
    if (!is_side_vertex(ring, i, rules)) corners.push_back(i);
  }
  if (corners.size() != 2) return std::nullopt;
  std::vector<Point2> s1, s2;
  for (size_t i = corners[0];; i = (i + 1) % n) {
    s1.push_back(ring[i]);
    if (i == corners[1]) break;
  }
  for (size_t i = corners[1];; i = (i + 1) % n) {
    s2.push_back(ring[i]);
    if (i == corners[0]) break;
  }
  std::optional<ScoredPieces> best;
  for (const double f : {1.0 / 3.0, 0.25, 0.4}) {
    for (const double w : {0.5, 0.35, 0.65}) {
      for (const double lambda : {0.15, 0.0, 0.3}) {
        std::optional<std::vector<QuadPiece>> pieces = two_corner_pieces(s1, s2, f, w, lambda, region.quantum());
        if (!pieces || !pieces_well_shaped(*pieces) || !two_corner_spokes_clear(region, *pieces)) continue;
        const double score = pieces_patch_jacobian(*pieces);
        if (score > 0.0 && (!best || score > best->score)) best = ScoredPieces{std::move(*pieces), score};
      }
    }
  }
  return best;
}

}  // namespace

bool smooth_template(const Region& region, const BlockRules& rules) {
  return applicable_smooth_template(region, rules).has_value();
}

bool two_corner_template(const Region& region, const BlockRules& rules) {
  return applicable_two_corner_template(region, rules).has_value();
}

bool ogrid_template(const Region& region, const BlockRules& rules) {
  return applicable_ogrid_template(region, rules).has_value();
}

bool tight_ogrid_template(const Region& region, const BlockRules& rules) {
  const std::optional<std::vector<QuadPiece>> pieces = applicable_ogrid_template(region, rules);
  return pieces && pieces->size() == 4;
}

bool roomy_ogrid_template(const Region& region, const BlockRules& rules) {
  const std::optional<std::vector<QuadPiece>> pieces = applicable_ogrid_template(region, rules);
  return pieces && pieces->size() == 12;
}

namespace {

// A template's foot within this fraction of the shorter edge beside a side vertex is that vertex.
constexpr double kFootOnVertex = 0.05;

// The usual template's pieces (block.h): one per corner, around the centre of the largest circle in
// the polygon of its corners (with fallback corners on a part with fewer than three).
std::vector<QuadPiece> usual_template_pieces(const Region& region, const BlockRules& rules) {
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  const std::vector<size_t> corners = template_corners(ring, rules);
  const size_t m = corners.size();
  auto next = [n](size_t i) { return (i + 1) % n; };
  auto length = [](Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); };
  // Side k (corner k to corner k + 1) split where its spoke meets it: the boundary vertices before
  // that point (from corner k), the point, and the vertices after it (up to corner k + 1, exclusive).
  struct Split {
    std::vector<Point2> before, after;
    Point2 foot;
  };
  std::vector<Split> splits(m);
  const double q = region.quantum();
  std::vector<Point2> corner_polygon;
  for (size_t k : corners) corner_polygon.push_back(ring[k]);
  const Point2 c = largest_inscribed_centre(corner_polygon);
  for (size_t k = 0; k < m; ++k) {
    // The side's vertices, corner k to corner k + 1 inclusive, and their distances along it.
    std::vector<Point2> side{ring[corners[k]]};
    std::vector<double> at{0.0};
    for (size_t i = corners[k]; i != corners[(k + 1) % m]; i = next(i)) {
      side.push_back(ring[next(i)]);
      at.push_back(at.back() + length(ring[i], ring[next(i)]));
    }
    // Where the spoke meets the side: the foot of the perpendicular from the centre on the chord
    // between the side's corners, kept within the side's middle half.
    const Point2 a = side.front(), b = side.back();
    const double chord2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
    const double foot = chord2 > 0.0 ? ((c.x - a.x) * (b.x - a.x) + (c.y - a.y) * (b.y - a.y)) / chord2 : 0.5;
    const double split_at = std::clamp(foot, 0.25, 0.75) * at.back();
    Split& s = splits[k];
    // A side vertex within the quantum of that point is the point; so is one within kFootOnVertex of
    // the shorter edge beside it, which would otherwise leave a hair-thin edge between the two (its
    // quads triangles with an edge of no length: a foot 0.009 from a vertex on sides of 8.8).
    size_t on_vertex = 0;
    double nearest = 1e300;
    for (size_t v = 1; v + 1 < side.size(); ++v) {
      const double off = std::fabs(at[v] - split_at);
      const double reach = std::max(q, kFootOnVertex * std::min(at[v] - at[v - 1], at[v + 1] - at[v]));
      if (off <= reach && off < nearest) {
        nearest = off;
        on_vertex = v;
      }
    }
    for (size_t v = 0; v + 1 < side.size(); ++v) {
      if (on_vertex != 0 ? v < on_vertex : at[v] < split_at) s.before.push_back(side[v]);
      else if (on_vertex != 0 ? v > on_vertex : true) s.after.push_back(side[v]);
    }
    if (on_vertex != 0) {
      s.foot = side[on_vertex];
    } else {
      size_t v = 0;
      while (v + 2 < side.size() && at[v + 1] < split_at) ++v;
      const double e = at[v + 1] - at[v];
      const double t = e > 0.0 ? (split_at - at[v]) / e : 0.0;
      s.foot = Point2{side[v].x + t * (side[v + 1].x - side[v].x), side[v].y + t * (side[v + 1].y - side[v].y)};
    }
  }
  std::vector<QuadPiece> pieces;
  for (size_t k = 0; k < m; ++k) {
    const Split& out = splits[k];
    const Split& in = splits[(k + m - 1) % m];
    QuadPiece piece;
    piece.ring = out.before;  // corner k first
    piece.corners[1] = static_cast<int>(piece.ring.size());
    piece.ring.push_back(out.foot);
    piece.corners[2] = static_cast<int>(piece.ring.size());
    piece.ring.push_back(c);
    piece.corners[3] = static_cast<int>(piece.ring.size());
    piece.ring.push_back(in.foot);
    piece.ring.insert(piece.ring.end(), in.after.begin(), in.after.end());
    piece.corners[0] = 0;
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

}  // namespace

namespace {

// A part without holes: the template's default pieces (the smooth template's, else the usual one's).
std::vector<QuadPiece> default_template_pieces(const Region& region, const BlockRules& rules) {
  if (std::optional<std::vector<QuadPiece>> smooth = applicable_smooth_template(region, rules)) return std::move(*smooth);
  return usual_template_pieces(region, rules);
}

}  // namespace

std::vector<QuadPiece> template_pieces(const Region& region, const BlockRules& rules, bool two_corner) {
  if (!region.holes().empty()) {
    if (std::optional<std::vector<QuadPiece>> ogrid = applicable_ogrid_template(region, rules)) return std::move(*ogrid);
    throw std::logic_error("template_pieces: a part with holes takes only the O-grid template");
  }
  std::vector<QuadPiece> pieces = default_template_pieces(region, rules);
  // A part with two corners, asked to: the two-corner template where it beats the smooth template or
  // the usual template's fallback corners.
  if (two_corner) {
    std::optional<ScoredPieces> two = applicable_two_corner_template(region, rules);
    if (two && two->score > pieces_patch_jacobian(pieces)) return std::move(two->pieces);
  }
  return pieces;
}

bool two_corner_improves(const Region& region, const BlockRules& rules) {
  if (!region.holes().empty()) return false;
  const std::optional<ScoredPieces> two = applicable_two_corner_template(region, rules);
  return two && two->score > pieces_patch_jacobian(default_template_pieces(region, rules));
}

std::vector<std::array<Point2, 4>> template_quads(const Region& region, const BlockRules& rules) {
  std::vector<std::array<Point2, 4>> quads;
  for (const QuadPiece& p : template_pieces(region, rules)) {
    quads.push_back({p.ring[static_cast<size_t>(p.corners[0])], p.ring[static_cast<size_t>(p.corners[1])],
                     p.ring[static_cast<size_t>(p.corners[2])], p.ring[static_cast<size_t>(p.corners[3])]});
  }
  return quads;
}

namespace {

// Inputs: t, a boundary corner's interior angle (radians). Output: the best scaled Jacobian of k quads
//         splitting it, over k >= 1: sin(t / k) is largest for t / k nearest a right angle.
double best_corner_split(double t) {
  const double k0 = std::max(1.0, std::floor(t / (0.5 * M_PI)));
  return std::max(std::sin(t / k0), std::sin(t / (k0 + 1.0)));
}

// Inputs: the turn from an incoming to an outgoing direction (radians). Output: the interior angle
//         for the region on the left, in (0, 2 pi).
double interior_of_turn(double turn) {
  while (turn <= -M_PI) turn += 2.0 * M_PI;
  while (turn > M_PI) turn -= 2.0 * M_PI;
  return M_PI - turn;
}

}  // namespace

std::vector<BoundaryCorner> boundary_corners(const std::vector<Ring>& loops, const FaceArcs& arcs) {
  std::vector<BoundaryCorner> corners;
  for (const Ring& ring : loops) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Point2 prev = ring[(i + n - 1) % n], at = ring[i], next = ring[(i + 1) % n];
      const int arc_in = arcs.empty() ? -1 : arcs.arc_of_chord(prev, at);
      const int arc_out = arcs.empty() ? -1 : arcs.arc_of_chord(at, next);
      if (arc_in >= 0 && arc_in == arc_out) continue;  // inside an arc: smooth
      // The directions of travel at the vertex: along an edge, or along an arc's tangent there.
      auto direction = [&](int arc, Point2 from, Point2 to) {
        double dx = to.x - from.x, dy = to.y - from.y;
        if (arc >= 0) {
          const CircularArc& c = arcs.arcs[static_cast<size_t>(arc)];
          const double rx = at.x - c.center.x, ry = at.y - c.center.y;
          double tx = -ry, ty = rx;  // the tangent, turned the way the chord runs
          if (tx * dx + ty * dy < 0) tx = -tx, ty = -ty;
          dx = tx, dy = ty;
        }
        return std::atan2(dy, dx);
      };
      const double t = interior_of_turn(direction(arc_out, at, next) - direction(arc_in, prev, at));
      // A tangent join (an arc's end meeting its neighbour smoothly) is no corner.
      if (std::fabs(t - M_PI) < 1e-9) continue;
      corners.push_back({at, t, arc_in, arc_out});
    }
  }
  return corners;
}

std::vector<double> boundary_corner_angles(const std::vector<Ring>& loops, const FaceArcs& arcs) {
  std::vector<double> angles;
  for (const BoundaryCorner& c : boundary_corners(loops, arcs)) angles.push_back(c.angle);
  return angles;
}

double scaled_jacobian_bound(const std::vector<Ring>& loops) { return scaled_jacobian_bound(loops, FaceArcs{}); }

double scaled_jacobian_bound(const std::vector<Ring>& loops, const FaceArcs& arcs) {
  double bound = 1.0;
  for (const double t : boundary_corner_angles(loops, arcs)) bound = std::min(bound, best_corner_split(t));
  return bound;
}

double topology_jacobian_bound(const std::vector<Ring>& loops, const FaceArcs& arcs) {
  const std::vector<double> angles = boundary_corner_angles(loops, arcs);
  const int holes = static_cast<int>(loops.size()) - 1;
  const int n = static_cast<int>(angles.size());
  constexpr int kMaxSplit = 8;  // quads at one corner: more would leave angles under 45 degrees of a 360
  // The scaled Jacobians a corner can have (sin(t / k), k = 1..kMaxSplit) are the thresholds tried.
  std::vector<double> thresholds{1.0};
  for (const double t : angles) {
    for (int k = 1; k <= kMaxSplit; ++k) thresholds.push_back(std::sin(t / k));
  }
  std::sort(thresholds.begin(), thresholds.end(), std::greater<double>());
  const double valence_five = std::sin(0.4 * M_PI), valence_three = std::sin(2.0 * M_PI / 3.0);
  double best = 0.0;
  for (const double tau : thresholds) {
    if (tau <= best) break;
    // Each corner's splits k with sin(t / k) >= tau form an interval (sin(t / k) is unimodal in k);
    // their sum K over the corners ranges over [low, high].
    int low = 0, high = 0;
    bool feasible = true;
    for (const double t : angles) {
      int lo = 0, hi = 0;
      for (int k = 1; k <= kMaxSplit; ++k) {
        if (std::sin(t / k) >= tau - 1e-12) {
          if (lo == 0) lo = k;
          hi = k;
        }
      }
      if (lo == 0) {
        feasible = false;
        break;
      }
      low += lo;
      high += hi;
    }
    if (!feasible) continue;
    // The index the interior must make up: D = 4 (1 - holes) - sum over corners of (2 - k).
    const int d_low = 4 * (1 - holes) - 2 * n + low, d_high = 4 * (1 - holes) - 2 * n + high;
    const double topology = d_low <= 0 && d_high >= 0 ? 1.0 : (d_high < 0 ? valence_five : valence_three);
    best = std::max(best, std::min(tau, topology));
  }
  return best;
}

BlockRules mesh_block_rules(const std::vector<Ring>& loops, double fraction) {
  BlockRules rules;
  const double least = std::asin(std::clamp(fraction * scaled_jacobian_bound(loops), 0.0, 1.0)) * 180.0 / M_PI;
  rules.min_corner_degrees = least;
  rules.max_corner_degrees = 180.0 - least;
  return rules;
}

OrientedRectangle min_area_rectangle(const Region& region) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_2> points, hull;
  if (region.is_convex()) {
    // Its own hull (counter-clockwise, no three vertices collinear in canonical form).
    for (const Point2& p : region.outer()) hull.emplace_back(p.x, p.y);
  } else {
    for (const Point2& p : region.outer()) points.emplace_back(p.x, p.y);
    CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  }
  // Rotating calipers: the minimum rectangle has a side along an edge of the hull. Coordinates are
  // taken relative to the hull's first vertex to keep digits for faces far from the origin.
  const double ox = hull[0].x(), oy = hull[0].y();
  OrientedRectangle best;
  double best_area = -1.0, best_tilt = 0.0;
  const size_t n = hull.size();
  for (size_t i = 0; i < n; ++i) {
    const double ex = hull[(i + 1) % n].x() - hull[i].x(), ey = hull[(i + 1) % n].y() - hull[i].y();
    const double len = std::hypot(ex, ey);
    if (len == 0.0) continue;
    double ux = ex / len, uy = ey / len;
    // Fold the axis into [0, 90) degrees: the same rectangle whichever of its sides is first.
    while (!(ux > 0.0 && uy >= 0.0)) {
      const double t = ux;
      ux = uy;
      uy = -t;
    }
    double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
    for (const K::Point_2& p : hull) {
      const double x = p.x() - ox, y = p.y() - oy;
      const double u = x * ux + y * uy, v = -x * uy + y * ux;
      umin = std::min(umin, u);
      umax = std::max(umax, u);
      vmin = std::min(vmin, v);
      vmax = std::max(vmax, v);
    }
    const double area = (umax - umin) * (vmax - vmin);
    // Prefer the smaller area; within a relative 1e-12 of it, the axis nearest X or Y (the tilt
    // computed only when it decides).
    const bool smaller = best_area < 0.0 || area < best_area * (1.0 - 1e-12);
    if (!smaller && !(area <= best_area * (1.0 + 1e-12))) continue;
    const double tilt = std::min(std::atan2(uy, ux), M_PI / 2 - std::atan2(uy, ux));
    if (smaller || tilt < best_tilt) {
      best_area = area;
      best_tilt = tilt;
      const double cu = 0.5 * (umin + umax), cv = 0.5 * (vmin + vmax);
      best.center = {ox + cu * ux - cv * uy, oy + cu * uy + cv * ux};
      best.axis = {ux, uy};
      best.width = umax - umin;
      best.height = vmax - vmin;
    }
  }
  return best;
}

}  // namespace autoblock
