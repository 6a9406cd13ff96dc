#include "core/region/region_cut.h"
#include "core/region/region_candidates.h"

#include <cmath>
#include <algorithm>
#include <map>
#include <random>
#include <sstream>

#include <catch2/catch.hpp>

using autoblock::CutKind;
using autoblock::Point2;
using autoblock::Region;
using autoblock::RegionCut;
using autoblock::Ring;

namespace {
constexpr double kQ = 1e-7;

// A star polygon of n vertices at random angles (within their sectors) and radii in [r0, r1];
// lattice: rounded to integers (many vertices then line up with edges and axes).
Ring random_star(std::mt19937_64& rng, int n, double r0, double r1, bool lattice = false) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * (i + 0.8 * unit(rng)) / n, r = r0 + (r1 - r0) * unit(rng);
    Point2 p{r * std::cos(t), r * std::sin(t)};
    if (lattice) p = {std::round(p.x), std::round(p.y)};
    ring.push_back(p);
  }
  return ring;
}

double total_area(const std::vector<Region>& pieces) {
  double a = 0.0;
  for (const Region& p : pieces) a += p.area();
  return a;
}
}  // namespace

TEST_CASE("a full cut along the diagonal splits a square into two triangles", "[region][cut]") {
  const Region square(Ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, kQ);
  const auto outcome = autoblock::cut_region(square, {CutKind::Full, {0, 0}, {1, 1}});
  REQUIRE(outcome.pieces.size() == 2);
  for (const Region& piece : outcome.pieces) {
    CHECK(piece.outer().size() == 3);
    CHECK(piece.area() == Approx(0.5));
  }
  REQUIRE(outcome.chords.size() == 1);
}

TEST_CASE("cuts that separate nothing change nothing", "[region][cut]") {
  const Region square(Ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, kQ);
  // Along an edge.
  CHECK(autoblock::cut_region(square, {CutKind::Full, {0, 0}, {1, 0}}).pieces.size() == 1);
  // A partial cut pointing out of the square.
  CHECK(autoblock::cut_region(square, {CutKind::Partial, {0, 0}, {-1, -0.5}}).pieces.size() == 1);
  // A partial cut from the outer boundary to a hole leaves a slit: nothing separated.
  const Region holed(Ring{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {Ring{{4, 4}, {6, 4}, {6, 6}, {4, 6}}}, kQ);
  const auto slit = autoblock::cut_region(holed, {CutKind::Partial, {5, 0}, {0, 1}});
  REQUIRE(slit.pieces.size() == 1);
  CHECK(slit.pieces[0] == holed);
  // The full line through the hole separates the part in two, and the hole is gone.
  const auto through = autoblock::cut_region(holed, {CutKind::Full, {5, 0}, {0, 1}});
  REQUIRE(through.pieces.size() == 2);
  CHECK(through.pieces[0].holes().empty());
  CHECK(total_area(through.pieces) == Approx(96.0));
  CHECK(through.chords.size() == 2);
}

TEST_CASE("a partial cut ends at the first boundary it meets (a T-junction)", "[region][cut]") {
  // An L; the ray from the re-entrant corner (1, 1) along -x meets the left edge at (0, 1).
  const Region l(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, kQ);
  Point2 hit;
  REQUIRE(autoblock::partial_cut_end(l, {1, 1}, {-1, 0}, &hit));
  CHECK(hit == Point2{0, 1});
  const auto outcome = autoblock::cut_region(l, {CutKind::Partial, {1, 1}, {-1, 0}});
  REQUIRE(outcome.pieces.size() == 2);
  CHECK(outcome.pieces[0].area() == Approx(2.0));  // the lower rectangle
  CHECK(outcome.pieces[1].area() == Approx(1.0));
  CHECK(outcome.pieces[0].outer().size() == 4);  // (1, 1) and the T are merged away as collinear
  // The full line through (1, 1) along x cuts the L the same way here: the line leaves through (2, 1).
  CHECK(autoblock::cut_region(l, {CutKind::Full, {1, 1}, {1, 0}}).pieces.size() == 2);
}

TEST_CASE("a full cut at an angle crosses several times: every interior segment is cut", "[region][cut]") {
  // A U: the horizontal line y = 2 crosses both arms.
  const Region u(Ring{{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {1, 1}, {1, 3}, {0, 3}}, {}, kQ);
  const auto outcome = autoblock::cut_region(u, {CutKind::Full, {0, 2}, {1, 0}});
  CHECK(outcome.pieces.size() == 3);
  CHECK(outcome.chords.size() == 2);
  CHECK(total_area(outcome.pieces) == Approx(u.area()));
  // A slanted line through the corner (1, 1) at 30 degrees.
  const auto slanted = autoblock::cut_region(u, {CutKind::Full, {1, 1}, {std::cos(M_PI / 6), std::sin(M_PI / 6)}});
  CHECK(slanted.pieces.size() >= 2);
  CHECK(total_area(slanted.pieces) == Approx(u.area()).epsilon(1e-9));
}

TEST_CASE("random cuts of random polygons conserve area and give valid canonical pieces", "[region][cut]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int cut_count = 0;
  for (int shape = 0; shape < 60; ++shape) {
    // A star-shaped polygon around the origin with 5-14 vertices, and sometimes a hole.
    const int n = 5 + static_cast<int>(unit(rng) * 10);
    Ring outer;
    for (int i = 0; i < n; ++i) {
      const double t = 2 * M_PI * (i + 0.8 * unit(rng)) / n, r = 4 + 6 * unit(rng);
      outer.push_back({r * std::cos(t), r * std::sin(t)});
    }
    std::vector<Ring> holes;
    if (shape % 3 == 0) holes.push_back(Ring{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
    std::vector<Region> parts{Region(outer, holes, kQ)};
    const double area = parts[0].area();
    for (int step = 0; step < 6 && !parts.empty(); ++step) {
      const Region part = parts.back();
      parts.pop_back();
      const Ring& loop = part.loop(static_cast<int>(unit(rng) * part.loop_count()) % part.loop_count());
      const Point2 origin = loop[static_cast<size_t>(unit(rng) * loop.size()) % loop.size()];
      const double angle = unit(rng) * 2 * M_PI;
      const RegionCut cut{unit(rng) < 0.5 ? CutKind::Full : CutKind::Partial, origin, {std::cos(angle), std::sin(angle)}};
      const auto outcome = autoblock::cut_region(part, cut);
      // Rounding the new points to the lattice moves each by at most q / sqrt(2): the area changes by
      // at most q times the length cut, which is less than the part's perimeter.
      CHECK(std::fabs(total_area(outcome.pieces) - part.area()) <= kQ * autoblock::region_perimeter(part));
      for (const Region& piece : outcome.pieces) {
        CHECK(piece.area() > 0.0);
        CHECK(autoblock::signed_area(piece.outer()) > 0.0);
        parts.insert(parts.begin(), piece);
      }
      ++cut_count;
    }
    CHECK(std::fabs(total_area(parts) - area) <= 6 * kQ * autoblock::region_perimeter(Region(outer, holes, kQ)));
  }
  CHECK(cut_count > 300);
}

TEST_CASE("the fast partial cut of a part without holes agrees with the arrangement", "[region][cut]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, split = 0;
  for (int shape = 0; shape < 80; ++shape) {
    const int n = 5 + static_cast<int>(unit(rng) * 12);
    const Region part(random_star(rng, n, 4, 10), {}, kQ);
    for (int c = 0; c < 10; ++c) {
      const size_t i = static_cast<size_t>(unit(rng) * part.outer().size()) % part.outer().size();
      Point2 origin = part.outer()[i];
      if (c % 3 == 0) {  // a point on an edge
        const Point2 b = part.outer()[(i + 1) % part.outer().size()];
        origin = {autoblock::snap_to_lattice(0.5 * (origin.x + b.x), kQ), autoblock::snap_to_lattice(0.5 * (origin.y + b.y), kQ)};
      }
      const double angle = unit(rng) * 2 * M_PI;
      const RegionCut cut{CutKind::Partial, origin, {std::cos(angle), std::sin(angle)}};
      const auto fast = autoblock::cut_region(part, cut);
      if (c % 3 == 0) {
        // A point on an edge rounded to the lattice lies off the exact edge, where the arrangement
        // sees a chord that starts inside (a slit) and the fast path the edge: check the area only.
        CHECK(std::fabs(total_area(fast.pieces) - part.area()) <= kQ * autoblock::region_perimeter(part));
        continue;
      }
      const auto slow = autoblock::cut_region_by_arrangement(part, cut);
      REQUIRE(fast.pieces.size() == slow.pieces.size());
      for (size_t k = 0; k < fast.pieces.size(); ++k) CHECK(fast.pieces[k] == slow.pieces[k]);
      split += fast.pieces.size() > 1 ? 1 : 0;
      ++compared;
    }
  }
  CHECK(compared > 400);
  CHECK(split > 150);
}

TEST_CASE("the fast cuts agree with the arrangement on every candidate, with and without holes", "[region][cut]") {
  // Random star polygons (generic angles) and lattice polygons (integer vertices: axis, 45-degree
  // and edge-extension cuts run through other vertices and along edges), a third with one or two
  // holes, every candidate cut of the search (region_candidates), full and partial. Where no vertex
  // other than the origin lies near the cut line, the fast paths give the same pieces and chords
  // as the arrangement. Near such a vertex the paths read the rounding of the direction differently
  // (the fast paths put a vertex within half a quantum on the line, region_cut.cpp); there the fast
  // path's pieces must still tile the part.
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, split = 0, full = 0, near = 0, near_split = 0, holed_split = 0;
  for (int shape = 0; shape < 150; ++shape) {
    const int n = 5 + static_cast<int>(unit(rng) * 14);
    const bool lattice = shape % 2 == 1;
    auto star = [&](int count, double r0, double r1, Point2 centre) {
      Ring ring;
      for (int i = 0; i < count; ++i) {
        const double t = 2 * M_PI * (i + 0.8 * unit(rng)) / count, r = r0 + (r1 - r0) * unit(rng);
        Point2 p{centre.x + r * std::cos(t), centre.y + r * std::sin(t)};
        if (lattice) p = {std::round(p.x), std::round(p.y)};
        ring.push_back(p);
      }
      return ring;
    };
    const Ring outer = star(n, 5, 11, {0, 0});
    std::vector<Ring> holes;
    if (shape % 3 == 2) {
      holes.push_back(star(3 + static_cast<int>(unit(rng) * 4), 1, 2.5, {-0.5, 0}));
      if (shape % 2 == 0) holes.push_back(star(3, 0.5, 1, {3, 0.5}));
    }
    const Region part(outer, holes, kQ);
    if (part.is_empty() || static_cast<size_t>(part.loop_count()) != holes.size() + 1) continue;
    std::vector<Point2> vertices;
    for (int k = 0; k < part.loop_count(); ++k) vertices.insert(vertices.end(), part.loop(k).begin(), part.loop(k).end());
    for (const autoblock::RegionAction& action : autoblock::region_candidates(part)) {
      if (action.kind != autoblock::RegionAction::Kind::Cut) continue;
      // A partial cut from a point on an edge (rounded to the lattice, so off the exact edge) is one
      // the arrangement reads as a slit: compared in the test above by area only.
      const bool at_vertex = std::find(vertices.begin(), vertices.end(), action.cut.origin) != vertices.end();
      if (action.cut.kind == CutKind::Partial && !at_vertex) continue;
      const auto fast = autoblock::cut_region(part, action.cut);
      const Point2 o = action.cut.origin, d = action.cut.direction;
      const double length = std::hypot(d.x, d.y);
      const bool near_vertex = std::any_of(vertices.begin(), vertices.end(), [&](Point2 v) {
        return !(v == o) && std::fabs(d.x * (v.y - o.y) - d.y * (v.x - o.x)) / length < 1e-6;
      });
      if (near_vertex) {
        ++near;
        near_split += fast.pieces.size() > 1 ? 1 : 0;
        CHECK(std::fabs(total_area(fast.pieces) - part.area()) <= kQ * autoblock::region_perimeter(part));
        continue;
      }
      const auto slow = autoblock::cut_region_by_arrangement(part, action.cut);
      std::ostringstream what;
      what.precision(17);
      what << "shape " << shape << (action.cut.kind == CutKind::Full ? " full" : " partial") << " from " << o.x << "," << o.y
           << " along " << d.x << "," << d.y;
      for (int k = 0; k < part.loop_count(); ++k) {
        what << " loop";
        for (const Point2& p : part.loop(k)) what << " " << p.x << "," << p.y;
      }
      INFO(what.str());
      REQUIRE(fast.pieces.size() == slow.pieces.size());
      for (size_t k = 0; k < fast.pieces.size(); ++k) CHECK(fast.pieces[k] == slow.pieces[k]);
      REQUIRE(fast.chords.size() == slow.chords.size());
      for (size_t k = 0; k < fast.chords.size(); ++k) {
        CHECK(fast.chords[k].a == slow.chords[k].a);
        CHECK(fast.chords[k].b == slow.chords[k].b);
      }
      split += fast.pieces.size() > 1 ? 1 : 0;
      holed_split += fast.pieces.size() > 1 && !holes.empty() ? 1 : 0;
      full += action.cut.kind == CutKind::Full && fast.pieces.size() > 2 ? 1 : 0;
      ++compared;
    }
  }
  WARN("compared " << compared << " (" << split << " split, " << holed_split << " of parts with holes, " << full
                   << " full cuts in 3+ pieces), near a vertex " << near << " (" << near_split << " split)");
  CHECK(compared > 3000);
  CHECK(split > 1000);
  CHECK(holed_split > 300);
  CHECK(full > 100);  // full cuts that cross the part more than once
  CHECK(near_split > 500);
}

TEST_CASE("cuts with the same chords have the same pieces, and cut_region_if stops when told", "[region][cut]") {
  // Random star and lattice polygons without holes (lattice vertices: many candidates share their
  // chords, a ray from one vertex to another and the ray back, a full cut crossing the part once
  // and the partial cut along it). The search cuts each set of chords once (region_policy.cpp).
  std::mt19937_64 rng(4711);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int shared = 0, told = 0;
  for (int shape = 0; shape < 120; ++shape) {
    const int n = 5 + static_cast<int>(unit(rng) * 14);
    const Region part(random_star(rng, n, 5, 11, shape % 2 == 1), {}, kQ);
    if (part.is_empty()) continue;
    std::map<std::vector<double>, std::vector<Region>> by_chords;
    for (const autoblock::RegionAction& action : autoblock::region_candidates(part)) {
      if (action.kind != autoblock::RegionAction::Kind::Cut) continue;
      std::vector<double> key;
      bool called = false;
      const auto outcome = autoblock::cut_region_if(part, action.cut, [&](const std::vector<autoblock::Chord>& chords) {
        called = true;
        for (const auto& c : chords) key.insert(key.end(), {c.a.x, c.a.y, c.b.x, c.b.y});
        return true;
      });
      REQUIRE(outcome.has_value());
      const auto plain = autoblock::cut_region(part, action.cut);
      REQUIRE(outcome->pieces.size() == plain.pieces.size());
      for (size_t k = 0; k < plain.pieces.size(); ++k) CHECK(outcome->pieces[k] == plain.pieces[k]);
      if (!called) continue;
      ++told;
      // Told no chords: the cut separates nothing.
      if (key.empty()) CHECK(outcome->pieces.size() == 1);
      // Stopped when told: nothing is cut.
      CHECK_FALSE(autoblock::cut_region_if(part, action.cut, [](const std::vector<autoblock::Chord>&) { return false; }).has_value());
      const auto [at, inserted] = by_chords.insert({key, outcome->pieces});
      if (inserted || key.empty()) continue;
      ++shared;
      REQUIRE(at->second.size() == outcome->pieces.size());
      for (size_t k = 0; k < outcome->pieces.size(); ++k) CHECK(at->second[k] == outcome->pieces[k]);
    }
  }
  CHECK(told > 2000);
  CHECK(shared > 300);
}

TEST_CASE("loops_touch: the grid's answer is every vertex against every other loop's edges", "[region][cut]") {
  // Disks of many holes (more vertices than the brute force takes), a third of the holes put within a
  // quantum or two of the outer loop or of another hole: the grid of a large part must find every
  // vertex within a quantum of another loop's edge, as the quadratic reference does.
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double q = 0.01;
  auto brute = [&](const Region& r) {
    for (int a = 0; a < r.loop_count(); ++a) {
      for (int b = 0; b < r.loop_count(); ++b) {
        if (a == b) continue;
        const Ring& ring = r.loop(b);
        for (const Point2& v : r.loop(a)) {
          for (size_t i = 0; i < ring.size(); ++i) {
            if (autoblock::segment_distance_squared(v, ring[i], ring[(i + 1) % ring.size()]) <= q * q) return true;
          }
        }
      }
    }
    return false;
  };
  auto circle = [](Point2 c, double r, int n, bool clockwise) {
    Ring ring;
    for (int i = 0; i < n; ++i) {
      const double t = 2 * M_PI * (clockwise ? n - i : i) / n;
      ring.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
    }
    return ring;
  };
  int large = 0, touching = 0;
  for (int shape = 0; shape < 400; ++shape) {
    const int n = 20 + static_cast<int>(unit(rng) * 100);
    const Ring outer = circle({0, 0}, 10, n, false);
    std::vector<Ring> holes;
    const int count = 1 + static_cast<int>(unit(rng) * 8);
    Point2 last{0, 0};
    for (int h = 0; h < count; ++h) {
      const double r = 0.5 + unit(rng), t = 2 * M_PI * unit(rng);
      double d = (8.5 - r) * std::sqrt(unit(rng));
      if (unit(rng) < 0.2) d = 10 * std::cos(M_PI / n) - r - 2 * q * unit(rng);  // at the outer loop's chord
      Point2 c{d * std::cos(t), d * std::sin(t)};
      if (h > 0 && unit(rng) < 0.2) {  // beside the previous hole, a gap of about a quantum
        const double gap = 2 * r + 2 * q * unit(rng) - 0.5 * q;
        c = {last.x + gap, last.y};
      }
      holes.push_back(circle(c, r, 8 + static_cast<int>(unit(rng) * 40), true));
      last = c;
    }
    const Region part(outer, holes, q);
    if (part.is_empty()) continue;
    INFO("shape " << shape);
    const bool expected = brute(part);
    CHECK(autoblock::loops_touch(part) == expected);
    large += part.vertex_count() > 64 ? 1 : 0;
    touching += expected && part.vertex_count() > 64 ? 1 : 0;
  }
  CHECK(large > 300);
  CHECK(touching > 50);
}
