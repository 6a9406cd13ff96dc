#include "core/region/region_cut.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

namespace autoblock {
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

// True when a vertex of one loop lies within one quantum of another loop: the loops touch (a cut
// nearly along a hole's edge leaves a gap thinner than the lattice, which rounding closes).
bool loops_touch(const Region& region) {
  const double q = region.quantum();
  for (int a = 0; a < region.loop_count(); ++a) {
    for (int b = 0; b < region.loop_count(); ++b) {
      if (a == b) continue;
      const Ring& ra = region.loop(a);
      const Ring& rb = region.loop(b);
      for (const Point2& v : ra) {
        for (size_t i = 0; i < rb.size(); ++i) {
          if (segment_distance(v, rb[i], rb[(i + 1) % rb.size()]) <= q) return true;
        }
      }
    }
  }
  return false;
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

// The partial cut of a region without holes: the chord from the origin to the exact end splits its
// one loop into two chains (no arrangement needed). Returns false when the origin is not on the loop.
bool split_simple(const Region& region, const RegionCut& cut, std::vector<Region>* pieces, Chord* chord) {
  KPoint end;
  size_t eh = 0;
  if (!exact_partial_end(region, cut.origin, cut.direction, &end, &eh)) {
    pieces->clear();
    return true;
  }
  const Ring& ring = region.outer();
  const size_t n = ring.size();
  const double q = region.quantum();
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
  if (eo == n || eo == eh) return false;
  const Point2 hit = rounded(end, q);
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

// True when the pieces tile the part (rounding to the lattice changes the area by at most q per unit
// of boundary: a safety net, with loops that touch refused this holds by construction) and, unless
// the cut is forced, the cut keeps clear of the region's vertices and leaves no sliver: every vertex
// of the region that is not an end of a chord lies farther than 2 q from every chord, and no piece
// has an area of at most q times its perimeter. A cut that grazes a vertex, ends within 2 q of a
// corner, or leaves a neck or a sliver narrower than the lattice can tell is one that OpenCASCADE,
// cutting the real face at the face's tolerance, would read differently (see region_cut.h).
bool acceptable(const Region& region, const std::vector<Region>& pieces, const std::vector<Chord>& chords, bool forced) {
  const double q = region.quantum();
  double area = 0.0, length = 0.0;
  bool sliver = false;
  for (const Region& piece : pieces) {
    const double perimeter = region_perimeter(piece);
    area += piece.area();
    length += perimeter;
    sliver = sliver || piece.area() <= q * perimeter;
  }
  if (std::fabs(area - region.area()) > q * length) return false;
  if (forced) return true;
  if (sliver) return false;
  for (int k = 0; k < region.loop_count(); ++k) {
    for (const Point2& v : region.loop(k)) {
      for (const Chord& c : chords) {
        if ((v.x == c.a.x && v.y == c.a.y) || (v.x == c.b.x && v.y == c.b.y)) continue;
        if (segment_distance(v, c.a, c.b) <= 2.0 * q) return false;
      }
    }
  }
  return true;
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
  std::sort(outcome.pieces.begin(), outcome.pieces.end(), lower_left);
  // The chords: cut edges with the interior on at least one side.
  for (auto edge = arrangement.edges_begin(); edge != arrangement.edges_end(); ++edge) {
    const auto& data = edge->curve().data();
    if (std::find(data.begin(), data.end(), 0) == data.end()) continue;
    if (std::any_of(data.begin(), data.end(), [](int d) { return d > 0; })) continue;  // along the boundary
    if (!interior_face(edge->face(), boundary) && !interior_face(edge->twin()->face(), boundary)) continue;
    if (edge->face()->is_unbounded() && edge->twin()->face()->is_unbounded()) continue;
    outcome.chords.push_back({rounded(edge->source()->point(), q), rounded(edge->target()->point(), q)});
  }
  if (!acceptable(region, outcome.pieces, outcome.chords, cut.forced)) return unchanged;
  return outcome;
}

CutOutcome cut_region(const Region& region, const RegionCut& cut) {
  if (region.is_empty()) throw std::invalid_argument("cut_region: empty region");
  if (cut.kind == CutKind::Partial && region.holes().empty() && std::hypot(cut.direction.x, cut.direction.y) > 0.0) {
    CutOutcome outcome;
    Chord chord;
    if (split_simple(region, cut, &outcome.pieces, &chord)) {
      if (outcome.pieces.size() < 2 || !acceptable(region, outcome.pieces, {chord}, cut.forced)) return {{region}, {}};
      std::sort(outcome.pieces.begin(), outcome.pieces.end(), lower_left);
      outcome.chords.push_back(chord);
      return outcome;
    }
  }
  return cut_region_by_arrangement(region, cut);
}

}  // namespace autoblock
