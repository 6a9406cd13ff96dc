#include "core/region/region_cut.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

namespace autoblock {

// Every vertex against every other loop's edges would be quadratic in the part's size (a plate's part
// of 60 holes: millions of distances for each cut measured, a quarter of its search's time): on a
// part of more than kTouchBrute vertices, an edge is measured only against the vertices in the grid
// cells that its box, grown by a quantum, covers (any vertex within a quantum of it is among them).
constexpr int kTouchBrute = 64;
bool loops_touch(const Region& region) {
  const double q = region.quantum();
  auto near = [&](Point2 v, const Ring& ring, size_t i) {
    return segment_distance_squared(v, ring[i], ring[(i + 1) % ring.size()]) <= q * q;
  };
  const int total = region.vertex_count();
  if (total <= kTouchBrute) {
    for (int a = 0; a < region.loop_count(); ++a) {
      for (int b = 0; b < region.loop_count(); ++b) {
        if (a == b) continue;
        const Ring& rb = region.loop(b);
        for (const Point2& v : region.loop(a)) {
          for (size_t i = 0; i < rb.size(); ++i) {
            if (near(v, rb, i)) return true;
          }
        }
      }
    }
    return false;
  }
  const Box box = region.bbox();
  const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(total))));
  const double cell = std::max({box.width(), box.height(), q}) / side + q;
  auto column = [&](double x) { return std::clamp(static_cast<long>(std::floor((x - box.xmin) / cell)), 0L, long{side}); };
  auto row = [&](double y) { return std::clamp(static_cast<long>(std::floor((y - box.ymin) / cell)), 0L, long{side}); };
  // The vertices by cell, with their loops, in cells of (side + 1) squared.
  const size_t width = static_cast<size_t>(side) + 1;
  std::vector<std::vector<std::pair<int, const Point2*>>> cells(width * width);
  for (int a = 0; a < region.loop_count(); ++a) {
    for (const Point2& v : region.loop(a)) {
      cells[static_cast<size_t>(row(v.y)) * width + static_cast<size_t>(column(v.x))].push_back({a, &v});
    }
  }
  for (int b = 0; b < region.loop_count(); ++b) {
    const Ring& rb = region.loop(b);
    for (size_t i = 0; i < rb.size(); ++i) {
      const Point2 p = rb[i], r = rb[(i + 1) % rb.size()];
      const long c0 = column(std::min(p.x, r.x) - q), c1 = column(std::max(p.x, r.x) + q);
      const long r0 = row(std::min(p.y, r.y) - q), r1 = row(std::max(p.y, r.y) + q);
      for (long y = r0; y <= r1; ++y) {
        for (long x = c0; x <= c1; ++x) {
          for (const auto& [a, v] : cells[static_cast<size_t>(y) * width + static_cast<size_t>(x)]) {
            if (a != b && near(*v, rb, i)) return true;
          }
        }
      }
    }
  }
  return false;
}

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using KPoint = Kernel::Point_2;
using KSegment = Kernel::Segment_2;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
// Curve data: 0 for the cut, 1 + i for boundary edge i (the region on the edge's left).
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Curve = Traits::Curve_2;
using Arrangement = CGAL::Arrangement_2<Traits>;

KPoint exact(Point2 p) { return KPoint(p.x, p.y); }

// The region's boundary edges, in loop order, each running with the region on its left.
std::vector<KSegment> boundary_segments(const Region& region) {
  std::vector<KSegment> segments;
  for (int k = 0; k < region.loop_count(); ++k) {
    const Ring& ring = region.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) segments.emplace_back(exact(ring[i]), exact(ring[(i + 1) % ring.size()]));
  }
  return segments;
}

// True when the face lies inside the region: decided by any boundary edge on its boundary (the
// region lies on each edge's left; a halfedge has its face on its left).
bool interior_face(Arrangement::Face_const_handle face, const std::vector<KSegment>& boundary) {
  auto decide = [&](Arrangement::Ccb_halfedge_const_circulator first, int* verdict) {
    auto h = first;
    do {
      for (int data : h->curve().data()) {
        if (data <= 0) continue;
        const KSegment& edge = boundary[static_cast<size_t>(data - 1)];
        const bool same = CGAL::compare_xy(edge.source(), edge.target()) ==
                          CGAL::compare_xy(h->source()->point(), h->target()->point());
        *verdict = same ? 1 : 0;
        return;
      }
    } while (++h != first);
  };
  int verdict = -1;
  if (face->has_outer_ccb()) decide(face->outer_ccb(), &verdict);
  for (auto inner = face->inner_ccbs_begin(); verdict < 0 && inner != face->inner_ccbs_end(); ++inner) decide(*inner, &verdict);
  return verdict == 1;
}

Point2 rounded(const KPoint& p, double quantum) {
  return {snap_to_lattice(CGAL::to_double(p.x()), quantum), snap_to_lattice(CGAL::to_double(p.y()), quantum)};
}

Ring ccb_ring(Arrangement::Ccb_halfedge_const_circulator first, double quantum) {
  Ring ring;
  auto h = first;
  do {
    ring.push_back(rounded(h->source()->point(), quantum));
  } while (++h != first);
  return ring;
}

// Pieces in order of their outer loops' vertices, lowest then leftmost first (pieces that share
// their first vertex, as the two sides of a cut from a corner may, by the next ones).
bool lower_left(const Region& a, const Region& b) {
  const Ring& p = a.outer();
  const Ring& q = b.outer();
  for (size_t i = 0; i < p.size() && i < q.size(); ++i) {
    if (p[i].y != q[i].y) return p[i].y < q[i].y;
    if (p[i].x != q[i].x) return p[i].x < q[i].x;
  }
  return p.size() < q.size();
}

// A direction scaled so that origin + direction reaches beyond the region's bounding box.
KPoint far_point(const Region& region, Point2 origin, Point2 direction, double sign) {
  const Box box = region.bbox();
  const double reach = 2.0 * (std::hypot(box.width(), box.height()) + std::fabs(origin.x - box.xmin) +
                              std::fabs(origin.y - box.ymin)) + 1.0;
  const double length = std::hypot(direction.x, direction.y);
  return KPoint(origin.x + sign * direction.x / length * reach, origin.y + sign * direction.y / length * reach);
}

// The exact end of the partial cut (see partial_cut_end), or false.
bool exact_partial_end(const Region& region, Point2 origin, Point2 direction, KPoint* hit, size_t* hit_edge = nullptr) {
  if (!(std::hypot(direction.x, direction.y) > 0.0)) return false;
  const KPoint o = exact(origin);
  const Kernel::Ray_2 ray(o, far_point(region, origin, direction, 1.0));
  bool found = false;
  KPoint best;
  Kernel::FT best_d2 = 0;
  size_t best_edge = 0, edge_index = 0;
  auto consider = [&](const KPoint& p) {
    if (p == o) return;
    const Kernel::FT d2 = CGAL::squared_distance(o, p);
    if (!found || d2 < best_d2) {
      best = p;
      best_d2 = d2;
      best_edge = edge_index;
      found = true;
    }
  };
  const std::vector<KSegment> edges = boundary_segments(region);
  for (edge_index = 0; edge_index < edges.size(); ++edge_index) {
    const KSegment& edge = edges[edge_index];
    // An edge through the origin meets the ray there (no use) and elsewhere only when the ray runs
    // along it: decided on input points, so that no crossing equal to the origin is constructed (an
    // equality the interval filter cannot settle, which would force exact arithmetic).
    const bool at_source = edge.source() == o;
    if (at_source || edge.target() == o) {
      const KPoint& other = at_source ? edge.target() : edge.source();
      if (ray.has_on(other)) consider(other);
      continue;
    }
    if (!CGAL::do_intersect(ray, edge)) continue;
    const auto crossing = CGAL::intersection(ray, edge);
    if (!crossing) continue;
    if (const KPoint* p = boost::get<KPoint>(&*crossing)) {
      consider(*p);
    } else if (const KSegment* s = boost::get<KSegment>(&*crossing)) {
      consider(s->source());
      consider(s->target());
    }
  }
  if (!found) return false;
  // The ray must run through the interior before it meets the boundary.
  const KPoint mid = CGAL::midpoint(o, best);
  for (int k = 0; k < region.loop_count(); ++k) {
    std::vector<KPoint> ring;
    for (const Point2& p : region.loop(k)) ring.push_back(exact(p));
    const CGAL::Bounded_side side = CGAL::bounded_side_2(ring.begin(), ring.end(), mid, Kernel());
    if (side == CGAL::ON_BOUNDARY) return false;
    if ((k == 0) != (side == CGAL::ON_BOUNDED_SIDE)) return false;
  }
  *hit = best;
  if (hit_edge) *hit_edge = best_edge;
  return true;
}


// ---------------------------------------------------------------------------------------------
// The fast path for a region without holes. The arrangement (below) is general but slow: every
// point it constructs is a lazy exact number, and a cut through a vertex makes the interval filter
// fail at once. On one loop the cut needs no arrangement. The cut line is the line through the
// origin along the direction; a vertex lies on it when its distance from it is at most half a
// quantum (the lattice cannot tell such a vertex from one on the line: a crossing that near it
// would round onto it), otherwise strictly on one side. So a cut along an edge's extension runs
// through the edge's far vertex even though the direction, a unit vector in doubles, misses it by
// a rounding error (the arrangement reads such a cut by where that rounding error puts the line;
// tests compare the two away from such vertices). The only constructions are the crossings with
// edges whose ends lie on opposite sides, in doubles and rounded to the lattice, or exactly where
// that rounding is in doubt. The point-in-loop test is CGAL's exact predicate on doubles. Where a
// decision is too close to call (two crossings at nearly the same place along the line), the fast
// path gives up and the arrangement decides.

using FastKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using FPoint = FastKernel::Point_2;

FPoint fast(Point2 p) { return FPoint(p.x, p.y); }

double cross(Point2 u, Point2 v) { return u.x * v.y - u.y * v.x; }
Point2 minus(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
double norm(Point2 u) { return std::sqrt(u.x * u.x + u.y * u.y); }

// The cut line: origin o, unit direction u; sides with the half-quantum band as the line.
struct CutLine {
  Point2 o, u;
  double half_q;
  CutLine(Point2 origin, Point2 direction, double q) : o(origin), half_q(0.5 * q) {
    const double length = norm(direction);
    u = {direction.x / length, direction.y / length};
  }
  // +1 left, -1 right, 0 on the line (within half a quantum).
  int side(Point2 p) const {
    const double s = cross(u, minus(p, o));
    return s > half_q ? 1 : s < -half_q ? -1 : 0;
  }
  // The signed distance along the line from o.
  double along(Point2 p) const { return (p.x - o.x) * u.x + (p.y - o.y) * u.y; }
  Point2 far(double t) const { return {o.x + t * u.x, o.y + t * u.y}; }
};

// True when value / q lies clearly away from a half-integer (its rounding is not in doubt) by more
// than err / q.
bool clear_rounding(double value, double err, double q) {
  const double k = value / q;
  return std::fabs(k - std::floor(k) - 0.5) > err / q + 1e-9;
}

// The crossing of the line (o, f) with the edge (a, b), whose ends lie strictly on opposite sides of
// it: raw, in doubles (for ordering along the line), and on the lattice (exact where the rounding
// of the double value is in doubt).
struct Crossing {
  Point2 raw, snapped;
};

Crossing line_crossing(const CutLine& line, Point2 a, Point2 b, double q) {
  const Point2 e = minus(b, a);
  const double da = cross(line.u, minus(a, line.o)), db = cross(line.u, minus(b, line.o));
  const double s = da / (da - db);
  Crossing c;
  c.raw = {a.x + s * e.x, a.y + s * e.y};
  // Error bound (generous): the determinants' rounding, amplified by the angle between edge and line.
  const double amplify = norm(e) / (std::fabs(da) + std::fabs(db));
  const double err = 1e-13 * (norm(minus(a, line.o)) + norm(e) + std::fabs(c.raw.x) + std::fabs(c.raw.y)) * amplify;
  if (clear_rounding(c.raw.x, err, q) && clear_rounding(c.raw.y, err, q)) {
    c.snapped = {snap_to_lattice(c.raw.x, q), snap_to_lattice(c.raw.y, q)};
    return c;
  }
  // The exact crossing of the edge with the line through o along u (u's doubles taken exactly).
  const Kernel::Line_2 exact_line(exact(line.o), Kernel::Vector_2(line.u.x, line.u.y));
  const auto hit = CGAL::intersection(exact_line, KSegment(exact(a), exact(b)));
  const KPoint* p = hit ? boost::get<KPoint>(&*hit) : nullptr;
  c.snapped = p ? rounded(*p, q) : Point2{snap_to_lattice(c.raw.x, q), snap_to_lattice(c.raw.y, q)};
  return c;
}

// Where the ray from o along direction first meets the loop (a region without holes): Found (hit
// on the lattice, the number of the edge it lies on: the first of the two at a vertex, as
// exact_partial_end numbers them), None (the ray meets nothing, or runs outside or along the
// boundary first), or Unsure.
enum class FastVerdict { Found, None, Done, Unsure };

// Inside the region (strictly: inside the outer loop, outside every hole), decided exactly on the
// point's doubles: 1 inside, 0 on a loop, -1 outside.
int inside_region(const Region& region, Point2 point) {
  const FPoint x(point.x, point.y);
  for (int k = 0; k < region.loop_count(); ++k) {
    std::vector<FPoint> loop;
    loop.reserve(region.loop(k).size());
    for (const Point2& p : region.loop(k)) loop.push_back(fast(p));
    const CGAL::Bounded_side side = CGAL::bounded_side_2(loop.begin(), loop.end(), x, FastKernel());
    if (side == CGAL::ON_BOUNDARY) return 0;
    if ((k == 0) != (side == CGAL::ON_BOUNDED_SIDE)) return -1;
  }
  return 1;
}

FastVerdict fast_partial_end(const Region& region, Point2 o, Point2 direction, Point2* hit, int* hit_loop, size_t* hit_edge) {
  const double q = region.quantum();
  const CutLine line(o, direction, q);
  bool found = false, unsure = false;
  double best_t = 0.0;
  Point2 best_raw, best_snapped;
  size_t best_edge = 0;
  int best_loop = 0;
  auto consider = [&](Point2 raw, Point2 snapped, int loop, size_t edge) {
    const double t = line.along(raw);
    if (!(t > line.half_q)) return;  // the origin itself, or behind it
    if (found) {
      // The same point again (a vertex, from its second edge) is a tie the first edge wins;
      // distinct points too close along the line to order are left to the exact path.
      const bool same = snapped == best_snapped;
      if (!same && std::fabs(t - best_t) <= 1e-12 * (1.0 + std::fabs(t))) unsure = true;
      if (same || t >= best_t) return;
    }
    found = true;
    best_t = t;
    best_raw = raw;
    best_snapped = snapped;
    best_loop = loop;
    best_edge = edge;
  };
  for (int k = 0; k < region.loop_count(); ++k) {
    const Ring& ring = region.loop(k);
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % n];
      const int sa = line.side(a), sb = line.side(b);
      if (sa == sb && sa != 0) continue;
      if (sa == 0 || sb == 0) {
        if (sa == 0) consider(a, a, k, i);
        if (sb == 0) consider(b, b, k, i);
        continue;
      }
      // The crossing lies between its edge's ends along the line: an edge wholly behind the origin,
      // or wholly beyond the nearest point found (by more than the tie margin), cannot be nearer.
      const double ta = line.along(a), tb = line.along(b);
      const double lo = std::min(ta, tb), hi = std::max(ta, tb), margin = 1e-9 * (1.0 + std::fabs(lo) + std::fabs(hi));
      if (hi + margin < line.half_q) continue;
      if (found && lo - margin > best_t + 1e-12 * (1.0 + std::fabs(best_t))) continue;
      const Crossing c = line_crossing(line, a, b, q);
      consider(c.raw, c.snapped, k, i);
    }
  }
  if (unsure) return FastVerdict::Unsure;
  if (!found) return FastVerdict::None;
  // The ray must run through the interior before it meets the boundary: the midpoint (the open
  // segment meets no boundary) strictly inside the region.
  if (inside_region(region, {(o.x + best_raw.x) / 2.0, (o.y + best_raw.y) / 2.0}) != 1) return FastVerdict::None;
  *hit = best_snapped;
  *hit_loop = best_loop;
  *hit_edge = best_edge;
  return FastVerdict::Found;
}

// The full cut of a region without holes: the loop with the line's proper crossings inserted, the
// chords (the stretches of the line between consecutive points on it that run through the
// interior), and the pieces they cut the loop into. Unsure hands the cut to the arrangement.
struct LineNode {
  Point2 point;  // on the lattice
  double t;      // along the line (from the unrounded point)
  bool on_line;
};

// The first half of the full cut of a region without holes: the loop's nodes (its vertices with the
// line's proper crossings inserted) and the chords as pairs of node indices, in order along the line.
FastVerdict fast_full_chords(const Region& region, Point2 o, Point2 direction, std::vector<LineNode>* nodes_out,
                             std::vector<std::pair<size_t, size_t>>* cuts_out) {
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  const double q = region.quantum();
  const CutLine line(o, direction, q);
  using Node = LineNode;
  std::vector<Node>& nodes = *nodes_out;
  nodes.clear();
  nodes.reserve(n + 8);
  std::vector<int> side(n);
  for (size_t i = 0; i < n; ++i) side[i] = line.side(ring[i]);
  for (size_t i = 0; i < n; ++i) {
    const Point2 v = ring[i];
    nodes.push_back({v, line.along(v), side[i] == 0});
    const size_t j = (i + 1) % n;
    if (side[i] != 0 && side[j] != 0 && side[i] != side[j]) {
      const Crossing c = line_crossing(line, v, ring[j], q);
      nodes.push_back({c.snapped, line.along(c.raw), true});
    }
  }
  std::vector<size_t> along;
  for (size_t k = 0; k < nodes.size(); ++k) {
    if (nodes[k].on_line) along.push_back(k);
  }
  std::sort(along.begin(), along.end(), [&](size_t a, size_t b) { return nodes[a].t < nodes[b].t; });
  const size_t m = nodes.size();
  std::vector<FPoint> loop;
  loop.reserve(n);
  for (const Point2& p : ring) loop.push_back(fast(p));
  std::vector<std::pair<size_t, size_t>>& cuts = *cuts_out;  // chords as node indices
  cuts.clear();
  for (size_t k = 0; k + 1 < along.size(); ++k) {
    const size_t a = along[k], b = along[k + 1];
    if (std::fabs(nodes[a].t - nodes[b].t) <= 1e-12 * (1.0 + std::fabs(nodes[a].t))) return FastVerdict::Unsure;
    if ((a + 1) % m == b || (b + 1) % m == a) continue;  // along a boundary edge
    const Point2 m = line.far(0.5 * (nodes[a].t + nodes[b].t));
    const FPoint mid(m.x, m.y);
    const CGAL::Bounded_side where = CGAL::bounded_side_2(loop.begin(), loop.end(), mid, FastKernel());
    if (where == CGAL::ON_BOUNDARY) return FastVerdict::Unsure;
    if (where == CGAL::ON_BOUNDED_SIDE) cuts.emplace_back(a, b);
  }
  return FastVerdict::Done;
}

// The second half: the loop split along the chords found by fast_full_chords.
FastVerdict fast_full_split(const Region& region, const std::vector<LineNode>& nodes,
                            const std::vector<std::pair<size_t, size_t>>& cuts, std::vector<Region>* pieces,
                            std::vector<Chord>* chords) {
  const double q = region.quantum();
  const size_t m = nodes.size();
  pieces->clear();
  chords->clear();
  if (cuts.empty()) return FastVerdict::Done;
  // Split the loop (node indices in order) by one chord at a time; the other chords go with the
  // part that holds both their ends (chords do not cross).
  struct Part {
    std::vector<size_t> loop;
    std::vector<std::pair<size_t, size_t>> cuts;
  };
  std::vector<Part> work(1);
  for (size_t k = 0; k < m; ++k) work[0].loop.push_back(k);
  work[0].cuts = cuts;
  while (!work.empty()) {
    Part part = std::move(work.back());
    work.pop_back();
    if (part.cuts.empty()) {
      Ring r;
      for (size_t k : part.loop) r.push_back(nodes[k].point);
      Region piece(r, {}, q);
      if (!piece.is_empty()) pieces->push_back(std::move(piece));
      continue;
    }
    const auto [a, b] = part.cuts.back();
    part.cuts.pop_back();
    const auto ia = std::find(part.loop.begin(), part.loop.end(), a) - part.loop.begin();
    const auto ib = std::find(part.loop.begin(), part.loop.end(), b) - part.loop.begin();
    const size_t len = part.loop.size();
    if (static_cast<size_t>(ia) == len || static_cast<size_t>(ib) == len) return FastVerdict::Unsure;
    Part one, two;
    for (size_t k = static_cast<size_t>(ia);; k = (k + 1) % len) {
      one.loop.push_back(part.loop[k]);
      if (k == static_cast<size_t>(ib)) break;
    }
    for (size_t k = static_cast<size_t>(ib);; k = (k + 1) % len) {
      two.loop.push_back(part.loop[k]);
      if (k == static_cast<size_t>(ia)) break;
    }
    for (const auto& c : part.cuts) {
      auto holds = [&](const Part& p, size_t x) { return std::find(p.loop.begin(), p.loop.end(), x) != p.loop.end(); };
      if (holds(one, c.first) && holds(one, c.second)) one.cuts.push_back(c);
      else if (holds(two, c.first) && holds(two, c.second)) two.cuts.push_back(c);
      else return FastVerdict::Unsure;
    }
    work.push_back(std::move(one));
    work.push_back(std::move(two));
  }
  for (const auto& [a, b] : cuts) chords->push_back({nodes[a].point, nodes[b].point});
  return FastVerdict::Done;
}

// Chords in a canonical order (each from its lexicographically smaller end, then sorted), so that
// the fast path and the arrangement report the same outcome.
void canonical_chords(std::vector<Chord>* chords) {
  auto less = [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  for (Chord& c : *chords) {
    if (less(c.b, c.a)) std::swap(c.a, c.b);
  }
  std::sort(chords->begin(), chords->end(), [&](const Chord& u, const Chord& v) {
    if (!(u.a == v.a)) return less(u.a, v.a);
    return less(u.b, v.b);
  });
}


// The cut of a region with holes (full or partial), by tracing the faces of the planar graph of
// its loops and the chords: every loop with the cut's points inserted (its vertices within half a
// quantum of the line on it, the line's proper crossings, a partial cut's ends), the chords as
// edges both ways, and at every node the walk turns onto the first edge clockwise from the one it
// came along, so that the region lies on its left: each cycle is a piece's outer loop
// (counter-clockwise) or a hole (clockwise, which goes to the piece around it). A cycle that runs
// along a chord both ways is a slit: the cut separates nothing there, and the region is unchanged,
// as the arrangement decides. Unsure hands the cut to the arrangement.
FastVerdict fast_cut_with_holes(const Region& region, const RegionCut& cut, std::vector<Region>* pieces, std::vector<Chord>* chords) {
  const double q = region.quantum();
  const CutLine line(cut.origin, cut.direction, q);
  const int loops = region.loop_count();
  struct Node {
    Point2 point;
    double t;
    bool on_line;
  };
  std::vector<std::vector<Node>> nodes(static_cast<size_t>(loops));
  std::vector<std::pair<std::pair<int, size_t>, std::pair<int, size_t>>> cuts;  // chords as (loop, node) pairs
  pieces->clear();
  chords->clear();
  if (cut.kind == CutKind::Full) {
    for (int k = 0; k < loops; ++k) {
      const Ring& ring = region.loop(k);
      const size_t n = ring.size();
      std::vector<int> side(n);
      for (size_t i = 0; i < n; ++i) side[i] = line.side(ring[i]);
      auto& list = nodes[static_cast<size_t>(k)];
      for (size_t i = 0; i < n; ++i) list.push_back({ring[i], line.along(ring[i]), side[i] == 0});
      for (size_t i = n; i-- > 0;) {  // back to front, so that the indices before stay valid
        const size_t j = (i + 1) % n;
        if (side[i] == 0 || side[j] == 0 || side[i] == side[j]) continue;
        const Crossing c = line_crossing(line, ring[i], ring[j], q);
        if (c.snapped == ring[i] || c.snapped == ring[j]) return FastVerdict::Unsure;
        list.insert(list.begin() + static_cast<std::ptrdiff_t>(i + 1), Node{c.snapped, line.along(c.raw), true});
      }
    }
    std::vector<std::pair<int, size_t>> along;
    for (int k = 0; k < loops; ++k) {
      for (size_t i = 0; i < nodes[static_cast<size_t>(k)].size(); ++i) {
        if (nodes[static_cast<size_t>(k)][i].on_line) along.emplace_back(k, i);
      }
    }
    auto node = [&](const std::pair<int, size_t>& id) -> const Node& { return nodes[static_cast<size_t>(id.first)][id.second]; };
    std::sort(along.begin(), along.end(), [&](const auto& a, const auto& b) { return node(a).t < node(b).t; });
    for (size_t k = 0; k + 1 < along.size(); ++k) {
      const auto a = along[k], b = along[k + 1];
      if (std::fabs(node(a).t - node(b).t) <= 1e-12 * (1.0 + std::fabs(node(a).t))) return FastVerdict::Unsure;
      const size_t m = nodes[static_cast<size_t>(a.first)].size();
      if (a.first == b.first && ((a.second + 1) % m == b.second || (b.second + 1) % m == a.second)) continue;  // along a loop's edge
      const int where = inside_region(region, line.far(0.5 * (node(a).t + node(b).t)));
      if (where == 0) return FastVerdict::Unsure;
      if (where == 1) cuts.push_back({a, b});
    }
  } else {
    Point2 hit;
    int hit_loop = 0;
    size_t hit_edge = 0;
    const FastVerdict end = fast_partial_end(region, cut.origin, cut.direction, &hit, &hit_loop, &hit_edge);
    if (end != FastVerdict::Found) return end == FastVerdict::None ? FastVerdict::Done : FastVerdict::Unsure;
    for (int k = 0; k < loops; ++k) {
      for (const Point2& p : region.loop(k)) nodes[static_cast<size_t>(k)].push_back({p, 0.0, false});
    }
    // The origin: a vertex, or a point within a quantum of an edge (inserted there).
    std::pair<int, size_t> from{-1, 0};
    for (int k = 0; k < loops && from.first < 0; ++k) {
      const Ring& ring = region.loop(k);
      for (size_t i = 0; i < ring.size(); ++i) {
        if (ring[i] == cut.origin) {
          from = {k, i};
          break;
        }
      }
    }
    std::pair<int, size_t> on_edge{-1, 0};
    if (from.first < 0) {
      double nearest = q * q;
      for (int k = 0; k < loops; ++k) {
        const Ring& ring = region.loop(k);
        for (size_t i = 0; i < ring.size(); ++i) {
          const double d = segment_distance_squared(cut.origin, ring[i], ring[(i + 1) % ring.size()]);
          if (d <= nearest) {
            nearest = d;
            on_edge = {k, i};
          }
        }
      }
      if (on_edge.first < 0) return FastVerdict::Unsure;
    }
    // The end: a vertex of its edge, or inserted into it.
    const Ring& hit_ring = region.loop(hit_loop);
    std::pair<int, size_t> to{hit_loop, hit_edge};
    const bool hit_vertex = hit == hit_ring[hit_edge] || hit == hit_ring[(hit_edge + 1) % hit_ring.size()];
    if (hit_vertex) to.second = hit == hit_ring[hit_edge] ? hit_edge : (hit_edge + 1) % hit_ring.size();
    // Insert the later index first in a shared loop, so that the earlier stays valid.
    struct Insert {
      int loop;
      size_t after;
      Point2 point;
      bool is_origin;
    };
    std::vector<Insert> inserts;
    if (from.first < 0) inserts.push_back({on_edge.first, on_edge.second, cut.origin, true});
    if (!hit_vertex) inserts.push_back({hit_loop, hit_edge, hit, false});
    if (inserts.size() == 2 && inserts[0].loop == inserts[1].loop && inserts[0].after == inserts[1].after) return FastVerdict::Unsure;
    std::sort(inserts.begin(), inserts.end(), [](const Insert& a, const Insert& b) {
      return a.loop != b.loop ? a.loop < b.loop : a.after > b.after;
    });
    for (const Insert& ins : inserts) {
      auto& list = nodes[static_cast<size_t>(ins.loop)];
      list.insert(list.begin() + static_cast<std::ptrdiff_t>(ins.after + 1), Node{ins.point, 0.0, true});
    }
    // Find both ends by their points in their loops now that the insertions are done.
    auto find = [&](int k, Point2 p) -> std::pair<int, size_t> {
      const auto& list = nodes[static_cast<size_t>(k)];
      for (size_t i = 0; i < list.size(); ++i) {
        if (list[i].point == p) return {k, i};
      }
      return {-1, 0};
    };
    const std::pair<int, size_t> a = find(from.first >= 0 ? from.first : on_edge.first, cut.origin), b = find(hit_loop, hit);
    if (a.first < 0 || b.first < 0 || (a == b)) return FastVerdict::Unsure;
    cuts.push_back({a, b});
  }
  if (cuts.empty()) return FastVerdict::Done;

  // The planar graph: node ids per loop, edges along the loops (region on their left) and chords
  // both ways.
  std::vector<size_t> offset(static_cast<size_t>(loops) + 1, 0);
  for (int k = 0; k < loops; ++k) offset[static_cast<size_t>(k) + 1] = offset[static_cast<size_t>(k)] + nodes[static_cast<size_t>(k)].size();
  const size_t count = offset.back();
  std::vector<Point2> point(count);
  for (int k = 0; k < loops; ++k) {
    for (size_t i = 0; i < nodes[static_cast<size_t>(k)].size(); ++i) point[offset[static_cast<size_t>(k)] + i] = nodes[static_cast<size_t>(k)][i].point;
  }
  struct Edge {
    size_t from, to;
    int chord;  // -1 along a loop, else the chord's number
  };
  std::vector<Edge> edges;
  for (int k = 0; k < loops; ++k) {
    const size_t m = nodes[static_cast<size_t>(k)].size();
    for (size_t i = 0; i < m; ++i) edges.push_back({offset[static_cast<size_t>(k)] + i, offset[static_cast<size_t>(k)] + (i + 1) % m, -1});
  }
  for (size_t c = 0; c < cuts.size(); ++c) {
    const size_t a = offset[static_cast<size_t>(cuts[c].first.first)] + cuts[c].first.second;
    const size_t b = offset[static_cast<size_t>(cuts[c].second.first)] + cuts[c].second.second;
    if (point[a] == point[b]) return FastVerdict::Unsure;
    edges.push_back({a, b, static_cast<int>(c)});
    edges.push_back({b, a, static_cast<int>(c)});
    chords->push_back({point[a], point[b]});
  }
  std::vector<std::vector<size_t>> out(count);
  std::vector<double> angle(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    const Point2 u = point[edges[e].from], v = point[edges[e].to];
    if (u == v) return FastVerdict::Unsure;
    angle[e] = std::atan2(v.y - u.y, v.x - u.x);
    out[edges[e].from].push_back(e);
  }
  // The next edge of the cycle on the left of e: at e's end, the first outgoing edge clockwise from
  // the way back.
  auto next = [&](size_t e) {
    const Point2 u = point[edges[e].from], v = point[edges[e].to];
    const double back = std::atan2(u.y - v.y, u.x - v.x);
    size_t best = edges.size();
    double best_turn = 0.0;
    for (size_t f : out[edges[e].to]) {
      double turn = std::fmod(back - angle[f] + 4.0 * M_PI, 2.0 * M_PI);
      if (turn <= 0.0) turn = 2.0 * M_PI;  // straight back: only when nothing else
      if (best == edges.size() || turn < best_turn) {
        best = f;
        best_turn = turn;
      }
    }
    return best;
  };
  std::vector<bool> used(edges.size(), false);
  std::vector<Ring> outers, holes;
  for (size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    Ring cycle;
    std::vector<int> chord_uses(cuts.size(), 0);
    size_t e = first, steps = 0;
    do {
      if (e == edges.size() || used[e] || ++steps > edges.size()) return FastVerdict::Unsure;
      used[e] = true;
      cycle.push_back(point[edges[e].from]);
      if (edges[e].chord >= 0 && ++chord_uses[static_cast<size_t>(edges[e].chord)] == 2) {
        // A slit: the cut separates nothing.
        pieces->clear();
        chords->clear();
        return FastVerdict::Done;
      }
      e = next(e);
    } while (e != first);
    const double area = signed_area(cycle);
    if (area > 0.0) outers.push_back(std::move(cycle));
    else if (area < 0.0) holes.push_back(std::move(cycle));
  }
  // Each hole goes to the piece whose outer loop holds its first vertex.
  std::vector<std::vector<Ring>> piece_holes(outers.size());
  for (Ring& hole : holes) {
    size_t owner = outers.size();
    for (size_t k = 0; k < outers.size() && owner == outers.size(); ++k) {
      std::vector<FPoint> loop;
      for (const Point2& p : outers[k]) loop.push_back(fast(p));
      for (const Point2& v : hole) {
        const CGAL::Bounded_side side = CGAL::bounded_side_2(loop.begin(), loop.end(), fast(v), FastKernel());
        if (side == CGAL::ON_BOUNDED_SIDE) owner = k;
        if (side != CGAL::ON_BOUNDARY) break;
      }
    }
    if (owner == outers.size()) return FastVerdict::Unsure;
    piece_holes[owner].push_back(std::move(hole));
  }
  for (size_t k = 0; k < outers.size(); ++k) {
    Region piece(outers[k], piece_holes[k], q);
    if (piece.is_empty()) continue;
    if (!piece.holes().empty() && loops_touch(piece)) {
      pieces->clear();
      chords->clear();
      return FastVerdict::Done;
    }
    pieces->push_back(std::move(piece));
  }
  return FastVerdict::Done;
}

// The partial cut of a region without holes: the chord from the origin to the exact end splits its
// one loop into two chains (no arrangement needed). Returns false when the origin is not on the loop.
// verdict, hit, eh: fast_partial_end's.
bool split_simple(const Region& region, const RegionCut& cut, FastVerdict verdict, Point2 hit, size_t eh,
                  std::vector<Region>* pieces, Chord* chord) {
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  const double q = region.quantum();
  if (verdict == FastVerdict::None) {
    pieces->clear();
    return true;
  }
  if (verdict == FastVerdict::Unsure) {
    KPoint end;
    if (!exact_partial_end(region, cut.origin, cut.direction, &end, &eh)) {
      pieces->clear();
      return true;
    }
    hit = rounded(end, q);
  }
  // The edge the origin lies on (a vertex: the edge it starts).
  size_t eo = n;
  double nearest = q;
  for (size_t i = 0; i < n; ++i) {
    if (ring[i] == cut.origin) {
      eo = i;
      break;
    }
    const double d = segment_distance(cut.origin, ring[i], ring[(i + 1) % n]);
    if (d <= nearest) {
      nearest = d;
      eo = i;
    }
  }
  if (eo == n) return false;
  // The end on the origin's own edge: the ray ran along that edge (a direction along it, rounded,
  // passes the interior test by a rounding error). The cut separates nothing.
  if (eo == eh) {
    pieces->clear();
    return true;
  }
  Ring a{cut.origin}, b{hit};
  for (size_t k = (eo + 1) % n;; k = (k + 1) % n) {
    a.push_back(ring[k]);
    if (k == eh) break;
  }
  a.push_back(hit);
  for (size_t k = (eh + 1) % n;; k = (k + 1) % n) {
    b.push_back(ring[k]);
    if (k == eo) break;
  }
  b.push_back(cut.origin);
  pieces->clear();
  for (const Ring* r : {&a, &b}) {
    Region piece(*r, {}, q);
    if (!piece.is_empty()) pieces->push_back(std::move(piece));
  }
  *chord = {cut.origin, hit};
  return true;
}

}  // namespace

std::string cut_kind_name(CutKind kind) { return kind == CutKind::Full ? "full" : "partial"; }

bool partial_cut_end(const Region& region, Point2 origin, Point2 direction, Point2* hit) {
  KPoint end;
  if (!exact_partial_end(region, origin, direction, &end)) return false;
  *hit = rounded(end, region.quantum());
  return true;
}

namespace {

// A piece whose mean width (twice its area over its perimeter) is at most 16 quanta is a sliver: no
// block of it could be meshed (the block model merges vertices within 1.5 quanta).
constexpr double kSliverWidthQuanta = 8.0;
// A chord passing within this many quanta of a vertex that is not its end would leave an edge or a
// corner too small to mesh (the cut should have gone through the vertex: the candidates have that cut),
// or, nearly along an edge at that vertex, a strip that thin beside the chord: at 8 quanta (less than a
// sliver's mean width) such a strip could be neither cut off nor finished (face 1621 of the property
// test's stream, a random decomposition, was left with one); twice the sliver width keeps it cuttable.
constexpr double kClearanceQuanta = 32.0;

// True when the pieces tile the part (rounding to the lattice changes the area by at most q per unit
// of boundary: a safety net, with loops that touch refused this holds by construction), no piece is
// pinched (its loops touching at a point) or a sliver (area at most kSliverWidthQuanta q times its
// perimeter), and, unless the cut is forced, the cut keeps clear of the region's vertices: every
// vertex of the region that is not an end of a chord lies farther than kClearanceQuanta q from every
// chord. A cut that grazes a vertex, ends that close to a corner, or leaves a neck or a sliver that
// narrow is one that OpenCASCADE, cutting the real face at the face's tolerance, would read
// differently, and whose pieces the mesher could not use (see region_cut.h).
bool acceptable(const Region& region, const std::vector<Region>& pieces, const std::vector<Chord>& chords, bool forced) {
  const double q = region.quantum();
  double area = 0.0, length = 0.0;
  bool sliver = false;
  for (const Region& piece : pieces) {
    const double perimeter = region_perimeter(piece);
    area += piece.area();
    length += perimeter;
    sliver = sliver || piece.area() <= kSliverWidthQuanta * q * perimeter;
  }
  if (std::fabs(area - region.area()) > q * length) return false;
  // Two chords meeting at a point (a line through a hole's corner, tangent to the hole there) can
  // leave a piece whose loops touch at that point (a point twice among its vertices): a pinched part
  // no cut can finish. Refused, forced or not.
  auto chords_meet = [&] {
    for (size_t i = 0; i < chords.size(); ++i) {
      for (size_t j = i + 1; j < chords.size(); ++j) {
        const Chord& a = chords[i];
        const Chord& b = chords[j];
        if (a.a == b.a || a.a == b.b || a.b == b.a || a.b == b.b) return true;
      }
    }
    return false;
  };
  if (chords_meet()) {
    for (const Region& piece : pieces) {
      std::vector<Point2> points;
      for (int k = 0; k < piece.loop_count(); ++k) points.insert(points.end(), piece.loop(k).begin(), piece.loop(k).end());
      std::sort(points.begin(), points.end(), [](Point2 u, Point2 v) { return u.x < v.x || (u.x == v.x && u.y < v.y); });
      if (std::adjacent_find(points.begin(), points.end()) != points.end()) return false;
    }
  }
  if (sliver) return false;  // forced or not: a piece thinner than the lattice cannot be finished
  if (forced) return true;
  for (int k = 0; k < region.loop_count(); ++k) {
    for (const Point2& v : region.loop(k)) {
      for (const Chord& c : chords) {
        if ((v.x == c.a.x && v.y == c.a.y) || (v.x == c.b.x && v.y == c.b.y)) continue;
        if (segment_distance_squared(v, c.a, c.b) <= kClearanceQuanta * kClearanceQuanta * q * q) return false;
      }
    }
  }
  return true;
}

// The outcome of a cut, whichever path split the region: the region itself when the cut separates
// nothing or is not acceptable; else the pieces in lower-left order and the chords in canonical order.
CutOutcome finished_outcome(const Region& region, CutOutcome outcome, bool forced) {
  if (outcome.pieces.size() < 2 || !acceptable(region, outcome.pieces, outcome.chords, forced)) return {{region}, {}};
  std::sort(outcome.pieces.begin(), outcome.pieces.end(), lower_left);
  canonical_chords(&outcome.chords);
  return outcome;
}

}  // namespace

CutOutcome cut_region_by_arrangement(const Region& region, const RegionCut& cut) {
  if (region.is_empty()) throw std::invalid_argument("cut_region: empty region");
  CutOutcome unchanged{{region}, {}};
  if (!(std::hypot(cut.direction.x, cut.direction.y) > 0.0)) return unchanged;
  const std::vector<KSegment> boundary = boundary_segments(region);
  std::vector<Curve> curves;
  curves.reserve(boundary.size() + 2);
  for (size_t i = 0; i < boundary.size(); ++i) curves.emplace_back(boundary[i], static_cast<int>(i + 1));
  const KPoint o = exact(cut.origin);
  if (cut.kind == CutKind::Full) {
    curves.emplace_back(KSegment(o, far_point(region, cut.origin, cut.direction, 1.0)), 0);
    curves.emplace_back(KSegment(far_point(region, cut.origin, cut.direction, -1.0), o), 0);
  } else {
    // The chord ends at the exact boundary point, not at its rounding (which may miss the edge).
    KPoint end;
    if (!exact_partial_end(region, cut.origin, cut.direction, &end)) return unchanged;
    curves.emplace_back(KSegment(o, end), 0);
  }
  Arrangement arrangement;
  CGAL::insert(arrangement, curves.begin(), curves.end());

  const double q = region.quantum();
  CutOutcome outcome;
  for (auto face = arrangement.faces_begin(); face != arrangement.faces_end(); ++face) {
    if (face->is_unbounded() || !interior_face(face, boundary)) continue;
    // A cut edge with this face on both sides is a slit: the cut separates nothing there.
    auto has_slit = [&](Arrangement::Ccb_halfedge_const_circulator first) {
      auto h = first;
      do {
        if (h->twin()->face() == face) return true;
      } while (++h != first);
      return false;
    };
    if (has_slit(face->outer_ccb())) return unchanged;
    std::vector<Ring> holes;
    for (auto inner = face->inner_ccbs_begin(); inner != face->inner_ccbs_end(); ++inner) {
      if (has_slit(*inner)) return unchanged;
      holes.push_back(ccb_ring(*inner, q));
    }
    Region piece(ccb_ring(face->outer_ccb(), q), holes, q);
    if (piece.is_empty()) continue;
    if (!piece.holes().empty() && loops_touch(piece)) return unchanged;
    outcome.pieces.push_back(std::move(piece));
  }
  if (outcome.pieces.size() < 2) return unchanged;
  // The chords: cut edges with the interior on at least one side.
  for (auto edge = arrangement.edges_begin(); edge != arrangement.edges_end(); ++edge) {
    const auto& data = edge->curve().data();
    if (std::find(data.begin(), data.end(), 0) == data.end()) continue;
    if (std::any_of(data.begin(), data.end(), [](int d) { return d > 0; })) continue;  // along the boundary
    if (!interior_face(edge->face(), boundary) && !interior_face(edge->twin()->face(), boundary)) continue;
    if (edge->face()->is_unbounded() && edge->twin()->face()->is_unbounded()) continue;
    outcome.chords.push_back({rounded(edge->source()->point(), q), rounded(edge->target()->point(), q)});
  }
  return finished_outcome(region, std::move(outcome), cut.forced);
}


std::optional<CutOutcome> cut_region_if(const Region& region, const RegionCut& cut, const ChordsCheck& proceed) {
  if (region.is_empty()) throw std::invalid_argument("cut_region: empty region");
  if (std::hypot(cut.direction.x, cut.direction.y) > 0.0) {
    CutOutcome outcome;
    bool done = false;
    // The chords in canonical order, for proceed (a region without holes, a cut not forced).
    auto stopped = [&](std::vector<Chord> chords) {
      if (!proceed || cut.forced) return false;
      canonical_chords(&chords);
      return !proceed(chords);
    };
    if (!region.holes().empty()) {
      done = fast_cut_with_holes(region, cut, &outcome.pieces, &outcome.chords) == FastVerdict::Done;
    } else if (cut.kind == CutKind::Full) {
      std::vector<LineNode> nodes;
      std::vector<std::pair<size_t, size_t>> cuts;
      if (fast_full_chords(region, cut.origin, cut.direction, &nodes, &cuts) != FastVerdict::Unsure) {
        std::vector<Chord> chords;
        for (const auto& [a, b] : cuts) chords.push_back({nodes[a].point, nodes[b].point});
        if (stopped(std::move(chords))) return std::nullopt;
        done = fast_full_split(region, nodes, cuts, &outcome.pieces, &outcome.chords) == FastVerdict::Done;
      }
    } else {
      Point2 hit;
      int hit_loop = 0;
      size_t hit_edge = 0;
      const FastVerdict verdict = fast_partial_end(region, cut.origin, cut.direction, &hit, &hit_loop, &hit_edge);
      if (verdict != FastVerdict::Unsure) {
        std::vector<Chord> chords;
        if (verdict == FastVerdict::Found) chords.push_back({cut.origin, hit});
        if (stopped(std::move(chords))) return std::nullopt;
      }
      Chord chord;
      done = split_simple(region, cut, verdict, hit, hit_edge, &outcome.pieces, &chord);
      if (done && outcome.pieces.size() >= 2) outcome.chords.push_back(chord);
    }
    if (done) return finished_outcome(region, std::move(outcome), cut.forced);
  }
  return cut_region_by_arrangement(region, cut);
}

CutOutcome cut_region(const Region& region, const RegionCut& cut) { return *cut_region_if(region, cut, nullptr); }

std::optional<Point2> line_meets_outer(const Region& region, Point2 p, Point2 u) {
  const Ring& ring = region.outer();
  const size_t m = ring.size();
  for (size_t i = 0; i < m; ++i) {
    const Point2 a = ring[i], b = ring[(i + 1) % m];
    const double sa = cross(u, minus(a, p)), sb = cross(u, minus(b, p));
    if ((sa < 0.0) == (sb < 0.0) || sa == sb) continue;
    const double t = sa / (sa - sb);
    return Point2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  }
  return std::nullopt;
}

}  // namespace autoblock
