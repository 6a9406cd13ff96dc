#include "core/region/hole_division.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <catch2/catch.hpp>

#include "core/geometry/circular_arc.h"
#include "core/region/block.h"
#include "core/region/region_search.h"
#include "support/test_shapes.h"

using namespace autoblock;
using autoblock::test::round_hole;

namespace {

constexpr double kQ = 1e-7;

Point2 turned(Point2 p, double angle) {
  return {p.x * std::cos(angle) - p.y * std::sin(angle), p.x * std::sin(angle) + p.y * std::cos(angle)};
}

// A plate nx * pitch by ny * pitch with a hole of radius r in the middle of each pitch square, turned
// by angle about the origin.
Region perforated_plate(int nx, int ny, double pitch, double r, double angle) {
  Ring outer;
  for (const Point2 p : {Point2{0, 0}, Point2{nx * pitch, 0}, Point2{nx * pitch, ny * pitch}, Point2{0, ny * pitch}}) {
    outer.push_back(turned(p, angle));
  }
  std::vector<Ring> holes;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) holes.push_back(round_hole(turned({(i + 0.5) * pitch, (j + 0.5) * pitch}, angle), r));
  }
  return Region(outer, holes, kQ);
}

// A flange: a disk of radius 50 about the origin, a bore of radius 20 and `bolts` holes of radius 3
// on a circle of radius 36, the first at `phase` radians.
Region flange(int bolts, double phase) {
  Ring rim = round_hole({0.0, 0.0}, 50.0);
  std::reverse(rim.begin(), rim.end());  // counter-clockwise: the outer loop
  std::vector<Ring> holes{round_hole({0.0, 0.0}, 20.0)};
  for (int i = 0; i < bolts; ++i) {
    const double a = phase + 2.0 * M_PI * i / bolts;
    holes.push_back(round_hole({36.0 * std::cos(a), 36.0 * std::sin(a)}, 3.0));
  }
  return Region(rim, holes, kQ);
}

// Every part divided again while it has two holes or more; the parts left (and, if asked, every
// chord cut).
std::vector<Region> divide_all(const Region& face, std::vector<Chord>* chords = nullptr) {
  std::vector<Region> cells;
  std::function<void(const Region&)> divide = [&](const Region& part) {
    if (part.holes().size() < 2) {
      cells.push_back(part);
      return;
    }
    const std::optional<HoleDivision> division = divide_holes(part);
    REQUIRE(division.has_value());
    REQUIRE(division->outcome.pieces.size() >= 2);
    if (chords) chords->insert(chords->end(), division->outcome.chords.begin(), division->outcome.chords.end());
    for (const Region& piece : division->outcome.pieces) {
      CHECK(piece.holes().size() < part.holes().size());
      divide(piece);
    }
  };
  divide(face);
  return cells;
}

// The search's first action on part and its whole decomposition, under the mesh preset and with no
// clock (the same every run).
struct Searched {
  RegionAction first;
  RegionDecomposition decomposition;
};
Searched search_without_clock(const Region& part) {
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  RegionSearchOptions options;
  options.time_limit = 0.0;
  RegionSearchPolicy search(options);
  RegionEpisode episode(part, mesh);
  Searched out;
  out.first = search.choose(episode);
  RegionSearchPolicy again(options);
  out.decomposition = decompose_region(part, again, mesh);
  return out;
}

}  // namespace

TEST_CASE("divide_holes cuts a plate with a grid of round holes into one O-grid cell per hole", "[region][division]") {
  for (const double angle : {0.0, 0.5236, 1.9}) {
    INFO("angle " << angle);
    const Region plate = perforated_plate(4, 3, 10.0, 2.0, angle);
    // The first cut is the balanced one: between the second and third columns, six holes each side.
    const std::optional<HoleDivision> first = divide_holes(plate);
    REQUIRE(first.has_value());
    REQUIRE(first->outcome.pieces.size() == 2);
    CHECK(first->outcome.pieces[0].holes().size() == 6);
    CHECK(first->outcome.pieces[1].holes().size() == 6);
    REQUIRE(first->outcome.chords.size() == 1);
    const Chord chord = first->outcome.chords[0];
    const Point2 a = turned(chord.a, -angle), b = turned(chord.b, -angle);
    CHECK(a.x == Approx(20.0).margin(1e-5));
    CHECK(b.x == Approx(20.0).margin(1e-5));
    CHECK(std::fabs(a.y - b.y) == Approx(30.0).margin(1e-5));

    const std::vector<Region> cells = divide_all(plate);
    REQUIRE(cells.size() == 12);
    double area = 0.0;
    for (const Region& cell : cells) {
      REQUIRE(cell.holes().size() == 1);
      CHECK(cell.outer().size() == 4);  // a square around its hole
      CHECK(ogrid_template(cell));
      area += cell.area();
    }
    CHECK(area == Approx(plate.area()).epsilon(1e-7));
  }
}

TEST_CASE("divide_holes leaves a staggered row's holes to lines between them and refuses holes no line separates", "[region][division]") {
  // A staggered plate: rows 8 apart, holes of radius 2 (no line between rows is nearer a hole than 2,
  // a radius); the columns' extents overlap, so the rows come apart first.
  Ring outer{{0, 0}, {40, 0}, {40, 24}, {0, 24}};
  std::vector<Ring> holes;
  for (int row = 0; row < 3; ++row) {
    for (int i = 0; i < 4; ++i) holes.push_back(round_hole({5.0 + 10.0 * i + (row % 2) * 5.0, 4.0 + 8.0 * row}, 2.0));
  }
  const Region staggered(outer, holes, kQ);
  const std::vector<Region> cells = divide_all(staggered);
  CHECK(cells.size() == 12);
  double area = 0.0;
  for (const Region& cell : cells) {
    CHECK(cell.holes().size() == 1);
    area += cell.area();
  }
  CHECK(area == Approx(staggered.area()).epsilon(1e-7));

  // Three holes of radius 1 at the corners of a triangle of side 2.2: every direction's extents
  // overlap (the triangle's least height, 1.91, is below a diameter), so no line divides them.
  const double h = 2.2 * std::sqrt(3.0) / 2.0;
  const Region cluster(Ring{{-5, -5}, {8, -5}, {8, 8}, {-5, 8}},
                       {round_hole({0, 0}, 1.0), round_hole({2.2, 0}, 1.0), round_hole({1.1, h}, 1.0)}, kQ);
  CHECK_FALSE(divide_holes(cluster).has_value());
  // A part with one hole has nothing to divide.
  CHECK_FALSE(divide_holes(Region(outer, {round_hole({20, 12}, 2.0)}, kQ)).has_value());
}

TEST_CASE("divide_holes cuts a flange into sectors along radial lines through its bore", "[region][division]") {
  // No straight line misses both the bore and the bolt circle, so the lines run through the centre
  // of the rim and the bore, between the bolt holes: one sector per bolt hole, the bore cut across.
  for (const int bolts : {5, 6, 8}) {
    INFO(bolts << " bolt holes");
    const Region part = flange(bolts, 0.3);
    std::vector<Chord> chords;
    const std::vector<Region> cells = divide_all(part, &chords);
    CHECK(cells.size() == static_cast<size_t>(bolts));
    double area = 0.0;
    for (const Region& cell : cells) {
      CHECK(cell.holes().size() == 1);
      area += cell.area();
    }
    CHECK(area == Approx(part.area()).epsilon(1e-7));
    // Every chord lies on a line through the origin (to within the centre found from the sampled
    // circles) and runs from the bore to the rim.
    REQUIRE_FALSE(chords.empty());
    for (const Chord& c : chords) {
      const double length = std::hypot(c.b.x - c.a.x, c.b.y - c.a.y);
      CHECK(std::fabs(c.a.x * c.b.y - c.a.y * c.b.x) / length < 0.2);
      CHECK(length == Approx(30.0).epsilon(0.01));
    }
  }
}

TEST_CASE("the search divides a perforated plate along its ligaments and finishes every cell", "[region][division][search]") {
  const Region plate = perforated_plate(5, 4, 10.0, 2.5, 0.3);
  const Searched searched = search_without_clock(plate);
  const std::optional<HoleDivision> division = divide_holes(plate);
  REQUIRE(division.has_value());
  CHECK(searched.first.kind == RegionAction::Kind::Cut);
  CHECK(searched.first.cut.origin == division->cut.origin);
  CHECK(searched.first.cut.direction == division->cut.direction);
  const RegionDecomposition& d = searched.decomposition;
  REQUIRE(d.complete());
  CHECK_FALSE(d.time_capped);
  // The finished blocks and templates make up the plate.
  double area = 0.0;
  for (const FinishedRegion& f : d.finished) area += f.region.area();
  CHECK(area == Approx(plate.area()).epsilon(1e-7));
  // Without the division the search finishes the plate too, by scoring cuts.
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  RegionSearchOptions options;
  options.divide_holes = false;
  options.time_limit = 2.0;
  RegionSearchPolicy undivided(options);
  CHECK(decompose_region(plate, undivided, mesh).complete());
}

TEST_CASE("divide_sector cuts a square cell about each bolt hole of a wide sector, each an O-grid", "[region][division][arc]") {
  // A flange of four bolt holes: divide_holes halves it and leaves two holes a part, a quarter ring
  // each once halved again (divide_sector's bisector); a square cell about a hole (30 deep, radius 36
  // to its middle) is 47.7 degrees wide, the pitch 90. Divided (divide_holes from three holes,
  // divide_sector below) until nothing more is cut: four cells with a hole, and on either side of
  // each a sector without, 21.1 degrees wide.
  auto divide_all_sectors = [](const Region& face) {
    std::vector<Region> parts;
    std::function<void(const Region&)> divide = [&](const Region& part) {
      const std::optional<HoleDivision> division =
          part.holes().size() >= static_cast<size_t>(kDivideHoles) ? divide_holes(part) : divide_sector(part);
      if (!division) {
        parts.push_back(part);
        return;
      }
      REQUIRE(division->outcome.pieces.size() >= 2);
      for (const Region& piece : division->outcome.pieces) divide(piece);
    };
    divide(face);
    return parts;
  };
  const Region four = flange(4, 0.3);
  const std::vector<Region> parts = divide_all_sectors(four);
  double area = 0.0;
  size_t cells = 0, sectors = 0;
  const double half = 0.5 * 30.0 / 36.0;  // the cell's half angle
  for (const Region& part : parts) {
    area += part.area();
    // The part's angular width about the origin: its extreme vertex directions.
    double lo = 1e9, hi = -1e9;
    const Point2 c = part.centroid();
    const double axis = std::atan2(c.y, c.x);
    for (const Point2& v : part.outer()) {
      const double a = std::remainder(std::atan2(v.y, v.x) - axis, 2.0 * M_PI);
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
    if (part.holes().size() == 1) {
      ++cells;
      CHECK(hi - lo == Approx(2.0 * half).margin(0.01));
      CHECK(ogrid_template(part));  // an annular sector: the O-grid with its arcs as sides
    } else {
      CHECK(part.holes().empty());
      ++sectors;
      CHECK(hi - lo == Approx(0.25 * M_PI - half).margin(0.01));
    }
  }
  CHECK(cells == 4);
  CHECK(sectors == 8);
  CHECK(area == Approx(four.area()).epsilon(1e-7));
  // Eight bolt holes, 45 degrees apart: the sectors between the gaps' middles are narrower than a
  // square cell already; nothing more is cut.
  const std::vector<Region> eight = divide_all_sectors(flange(8, 0.3));
  CHECK(eight.size() == 8);
  for (const Region& part : eight) CHECK(part.holes().size() == 1);
  // A plate of two holes (no arcs about one centre), each hole's cell as long as it is wide: nothing
  // to divide.
  CHECK_FALSE(divide_sector(perforated_plate(2, 1, 10.0, 2.5, 0.3)).has_value());
}

TEST_CASE("divide_sector parts a flange's two bolt circles with chords, one O-grid cell a bolt hole", "[region][division][arc]") {
  // A flange of two bolt circles, twelve holes of radius 2.5 on each, in line, at radii 25 and 40
  // about a bore of radius 15 in a disk of radius 50. divide_holes cuts it into sectors (radial
  // lines, or chords between the circles), leaving two holes in line in a part; divide_sector cuts
  // the chord between them (before it, such a part was left to the search: 0.33 of the bound on a
  // flange of 24 and 24 holes, 0.85 with these cells).
  // The rim inscribed, as a face's convex arcs are (circular_arc.h), the holes circumscribed.
  CircularArc rim_arc;
  rim_arc.radius = 50.0;
  rim_arc.sweep = 2.0 * M_PI;
  Ring rim = polygonise_arc(rim_arc);
  rim.pop_back();  // a full circle ends where it starts
  std::vector<Ring> holes{round_hole({0.0, 0.0}, 15.0)};
  for (const double r : {25.0, 40.0}) {
    for (int i = 0; i < 12; ++i) {
      const double a = 0.2 + 2.0 * M_PI * i / 12;
      holes.push_back(round_hole({r * std::cos(a), r * std::sin(a)}, 2.5));
    }
  }
  const Region face(rim, holes, kQ);
  // Divided as the search divides: each piece given the centre its parent's division found (a
  // sector's rim and bore, polygonised in 15-degree steps and cut short, vote for centres far apart).
  std::vector<Region> parts;
  std::function<void(const Region&, std::optional<Point2>)> divide = [&](const Region& part, std::optional<Point2> hint) {
    const std::optional<HoleDivision> division =
        part.holes().size() >= static_cast<size_t>(kDivideHoles) ? divide_holes(part, hint) : divide_sector(part, hint);
    if (!division) {
      parts.push_back(part);
      return;
    }
    REQUIRE(division->outcome.pieces.size() >= 2);
    for (const Region& piece : division->outcome.pieces) divide(piece, division->centre ? division->centre : hint);
  };
  divide(face, std::nullopt);
  double area = 0.0;
  size_t cells = 0;
  for (const Region& part : parts) {
    area += part.area();
    REQUIRE(part.holes().size() <= 1);
    if (part.holes().size() == 1) {
      ++cells;
      CHECK(ogrid_template(part));  // a cell with a side along the bore or the rim, or none
    }
  }
  CHECK(cells == 24);
  CHECK(area == Approx(face.area()).epsilon(1e-7));
}

TEST_CASE("divide_sector cuts a plate's long strip at its hole's cell ends where the cell takes an O-grid", "[region][division][arc]") {
  // A strip 20 by 60 (a plate's, between two of divide_holes's lines), turned by 0.4, one hole of
  // radius 3 a little below its middle: no centre of arcs, so the cell's ends are cut square to the
  // strip's axis, the longer leftover first. Left: a square cell about the hole, an O-grid, and two
  // blocks.
  const double angle = 0.4;
  Ring outer;
  for (const Point2 p : {Point2{0, 0}, Point2{20, 0}, Point2{20, 60}, Point2{0, 60}}) outer.push_back(turned(p, angle));
  const Region strip(outer, {round_hole(turned({10, 25}, angle), 3.0)}, kQ);
  std::vector<Region> parts;
  std::function<void(const Region&)> divide = [&](const Region& part) {
    const std::optional<HoleDivision> division = part.holes().empty() ? std::nullopt : divide_sector(part);
    if (!division) {
      parts.push_back(part);
      return;
    }
    REQUIRE(division->outcome.pieces.size() == 2);
    REQUIRE(division->outcome.chords.size() == 1);
    // Square to the strip's axis: the chord runs across it, 20 long.
    const Chord chord = division->outcome.chords[0];
    CHECK(std::hypot(chord.b.x - chord.a.x, chord.b.y - chord.a.y) == Approx(20.0).margin(1e-5));
    for (const Region& piece : division->outcome.pieces) divide(piece);
  };
  divide(strip);
  REQUIRE(parts.size() == 3);
  double area = 0.0;
  for (const Region& part : parts) {
    area += part.area();
    if (part.holes().empty()) {
      CHECK(part.outer().size() == 4);
      continue;
    }
    CHECK(ogrid_template(part));
    CHECK(part.area() + M_PI * 9.0 == Approx(400.0).epsilon(0.01));  // the 20 by 20 cell, less the hole
  }
  CHECK(area == Approx(strip.area()).epsilon(1e-7));
  // A hole too near the strip's sides for an O-grid's box (radius 7, 3 from each side, 12 from its
  // end): the line at its cell's far end keeps 3 from it too, and leaves a tight cell (block.h), which
  // a tight O-grid takes. Without tight O-grids (BlockRules::tight_ogrid) the strip is left whole: a
  // line keeping half a radius would leave a short piece no O-grid takes.
  const Region tight(outer, {round_hole(turned({10, 12}, angle), 7.0)}, kQ);
  CHECK_FALSE(ogrid_template(tight));
  const std::optional<HoleDivision> end = divide_sector(tight);
  REQUIRE(end.has_value());
  REQUIRE(end->outcome.pieces.size() == 2);
  for (const Region& piece : end->outcome.pieces) {
    if (piece.holes().empty()) {
      CHECK(piece.area() == Approx(20.0 * 38.0).epsilon(1e-6));  // beyond the cell's end at 22
    } else {
      CHECK(tight_ogrid_template(piece));
    }
  }
  CHECK_FALSE(divide_sector(tight, std::nullopt, false).has_value());
}

TEST_CASE("the search divides a division's part of two holes with room between them, not two holes close together",
          "[region][division][search][arc]") {
  // A plate 40 by 10 with four holes of radius 2.5 in a row: divide_holes halves it, leaving two
  // strips 20 by 10 of two holes each (no centre of arcs, each hole's cell as long as the strip is
  // wide: divide_sector has nothing). divide_holes's line between a strip's holes leaves each a
  // clearance of a radius: room for both O-grids. The search takes it and finishes four O-grid cells.
  const Region plate = perforated_plate(4, 1, 10.0, 2.5, 0.3);
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  RegionSearchOptions options;
  options.time_limit = 0.0;  // no clock: the same decomposition every run
  RegionSearchPolicy search(options);
  RegionEpisode episode(plate, mesh);
  episode.step(search.choose(episode));
  const Region strip = episode.current_part();
  REQUIRE(strip.holes().size() == 2);
  REQUIRE_FALSE(divide_sector(strip).has_value());
  const std::optional<HoleDivision> roomy = divide_holes(strip, std::nullopt, true);
  REQUIRE(roomy.has_value());
  const RegionAction second = search.choose(episode);
  CHECK(second.kind == RegionAction::Kind::Cut);
  CHECK(second.cut.origin == roomy->cut.origin);
  CHECK(second.cut.direction == roomy->cut.direction);
  const Searched searched = search_without_clock(plate);
  const RegionDecomposition& d = searched.decomposition;
  REQUIRE(d.complete());
  REQUIRE(d.finished.size() == 4);
  for (const FinishedRegion& f : d.finished) {
    CHECK(f.is_template);
    CHECK(f.region.holes().size() == 1);
    CHECK(ogrid_template(f.region));
  }
  // The same holes 6 apart (a ligament of 1, a fifth of a radius on either side of a line between
  // them): divide_holes would thread a line there, with no room for an O-grid; the roomy division
  // refuses, and the search cuts the part itself.
  const Region close(perforated_plate(2, 1, 10.0, 2.5, 0.3).outer(),
                     {round_hole(turned({7, 5}, 0.3), 2.5), round_hole(turned({13, 5}, 0.3), 2.5)}, kQ);
  REQUIRE_FALSE(divide_sector(close).has_value());
  CHECK(divide_holes(close).has_value());
  CHECK_FALSE(divide_holes(close, std::nullopt, true).has_value());
}
