// The generator of faces with circular arcs: every kind at every scale is a valid face that
// AutoBlock's reader takes with its arcs, with the holes its kind promises.
#include "core/data/arc_generator.h"

#include <cmath>
#include <map>
#include <random>

#include <catch2/catch.hpp>

#include "core/common/error.h"
#include "core/geometry/occt_properties.h"
#include "core/io/input_face.h"

using namespace autoblock;

TEST_CASE("generated arc faces of every kind are valid, read with their arcs, at every scale", "[data][arc]") {
  std::mt19937_64 rng(20261202);
  for (int kind = 0; kind < kArcKinds; ++kind) {
    for (double scale : {0.1, 1.0, 100.0}) {
      for (int i = 0; i < 6; ++i) {
        const ArcFace f = random_arc_face(rng, static_cast<ArcKind>(kind), scale);
        INFO(arc_kind_name(f.kind) << " at scale " << scale << ": " << f.name);
        CHECK(f.kind == static_cast<ArcKind>(kind));
        REQUIRE(occt_shape_valid(f.face));
        const InputFace face = input_face_from_occt(f.face, f.name);
        REQUIRE(face.is_general());
        CHECK(face.arcs.arcs.size() > 0);
        CHECK(f.arcs > 0);
        CHECK(face.region.holes().size() == static_cast<size_t>(f.holes));
        // The face's size follows the scale (plates 6-24 by 4-14 of it, polygons up to 20, unions up to 72).
        const double size = face.region.bbox().longer_side();
        CHECK(size > 1.9 * scale);
        CHECK(size < 100.0 * scale);
        const double area = occt_area(f.face);
        CHECK(area > 0.0);
        CHECK(area < face.region.bbox().width() * face.region.bbox().height());
        switch (f.kind) {
          case ArcKind::PlateHoles: CHECK((f.holes >= 1 && f.holes <= 4)); break;
          case ArcKind::RoundedPlateHoles: CHECK((f.holes >= 1 && f.holes <= 3)); break;
          case ArcKind::SlottedPlate: CHECK(f.holes == 1); break;
          default: CHECK(f.holes == 0);
        }
      }
    }
  }
}

TEST_CASE("arc faces have the areas of their plates less their holes and slots", "[data][arc]") {
  const double pi = std::acos(-1.0);
  CHECK(occt_area(plate_with_holes(20, 10, {{4, 3, 1}, {12, 6, 2}})) == Approx(200 - pi * (1 + 4)).epsilon(1e-9));
  // A slot at an angle: a rectangle 2 r by its length plus two half disks.
  const Slot slot{{10, 6}, 5, 1.5, 0.6};
  CHECK(occt_area(slotted_plate(20, 12, slot)) == Approx(240 - (pi * 1.5 * 1.5 + 3 * 5)).epsilon(1e-9));
  CHECK(occt_area(slotted_plate()) == Approx(200 - (pi * 4 + 4 * 8)).epsilon(1e-9));
  // A square with one corner filleted loses r^2 (1 - pi / 4) there; with all four, four times that.
  const RectilinearPolygon square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}};
  CHECK(occt_area(filleted_polygon(square, 2.0, {1})) == Approx(100 - 4 * (1 - pi / 4)).epsilon(1e-9));
  CHECK(occt_area(filleted_polygon(square, std::vector<double>{2, 0, 3, 0})) == Approx(100 - 13 * (1 - pi / 4)).epsilon(1e-9));
  CHECK(occt_area(disk(1, 2, 3)) == Approx(9 * pi).epsilon(1e-9));
}

TEST_CASE("generate_arc_face mixes the kinds and scales, a quarter or more with holes, and repeats from a seed",
          "[data][arc]") {
  std::mt19937_64 rng(7), again(7);
  std::map<ArcKind, int> kinds;
  int with_holes = 0;
  double smallest = 1e300, largest = 0.0;
  const int count = 60;
  for (int i = 0; i < count; ++i) {
    const ArcFace f = generate_arc_face(rng, ArcOptions{});
    const ArcFace g = generate_arc_face(again, ArcOptions{});
    CHECK(occt_area(f.face) == occt_area(g.face));
    CHECK(f.name == g.name);
    ++kinds[f.kind];
    with_holes += f.holes > 0;
    const double area = occt_area(f.face);
    smallest = std::min(smallest, area);
    largest = std::max(largest, area);
  }
  CHECK(kinds.size() == static_cast<size_t>(kArcKinds));
  CHECK(4 * with_holes >= count);
  // Scales from 0.1 to 100: areas three or more orders of magnitude apart.
  CHECK(largest > 1000.0 * smallest);
  CHECK_THROWS_AS(generate_arc_face(rng, ArcOptions{2.0, 1.0}), InputError);
  CHECK_THROWS_AS(generate_arc_face(rng, ArcOptions{0.0, 1.0}), InputError);
}
