#include "core/region/face_frame.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "core/baselines/baseline_policy.h"
#include "core/data/shape_generator.h"
#include "core/geometry/tolerance.h"
#include "core/region/block.h"

using namespace autoblock;

TEST_CASE("a rectilinear face turned by any angle gets the blocks of its axis-aligned twin, turned", "[region][frame]") {
  std::mt19937_64 rng(44);
  GeneratorOptions options;
  options.holes = true;
  options.max_rects = 6;
  int turned_faces = 0;
  for (int f = 0; f < 6; ++f) {
    const GeneratedShape shape = generate_shape(rng, options);
    const double q = tolerance_for_size(ring_bbox(shape.polygon.outer).longer_side());
    const Region twin(shape.polygon.outer, shape.polygon.holes, q);
    const auto twin_frame = rectilinear_frame(twin);
    REQUIRE(twin_frame);
    CHECK(twin_frame->angle == 0.0);
    auto policy = make_baseline_policy("greedy", 1.0, {});
    std::vector<Region> twin_blocks;
    const Decomposition reference = decompose_in_frame(twin, *twin_frame, *policy, {}, &twin_blocks);
    REQUIRE(reference.complete());
    for (double degrees : {0.5, 17.0, 30.0, 45.0, 89.9, 90.0, 133.0, 271.0}) {
      const double t = degrees * M_PI / 180.0, c = std::cos(t), s = std::sin(t);
      auto turn = [&](const Ring& ring) {
        Ring out;
        for (const Point2& p : ring) out.push_back({1000.0 + c * p.x - s * p.y, -50.0 + s * p.x + c * p.y});
        return out;
      };
      std::vector<Ring> holes;
      for (const Ring& h : shape.polygon.holes) holes.push_back(turn(h));
      const Region turned(turn(shape.polygon.outer), holes, q);
      const auto frame = rectilinear_frame(turned);
      REQUIRE(frame);
      auto same_policy = make_baseline_policy("greedy", 1.0, {});
      std::vector<Region> blocks;
      const Decomposition d = decompose_in_frame(turned, *frame, *same_policy, {}, &blocks);
      REQUIRE(d.complete());
      // The same number of blocks, of the same areas and shapes (rectangles), covering the face.
      REQUIRE(blocks.size() == twin_blocks.size());
      double area = 0.0, twin_area = 0.0;
      std::vector<double> areas, twin_areas;
      for (const Region& b : blocks) {
        CHECK(is_block(b));
        areas.push_back(b.area());
        area += b.area();
      }
      for (const Region& b : twin_blocks) {
        twin_areas.push_back(b.area());
        twin_area += b.area();
      }
      std::sort(areas.begin(), areas.end());
      std::sort(twin_areas.begin(), twin_areas.end());
      // Turned coordinates lie on the lattice, within q / sqrt(2) of the exact turn: areas agree within
      // q times the perimeter.
      double perimeter = 0.0;
      for (const Region& b : twin_blocks) {
        const OrientedRectangle r = min_area_rectangle(b);
        perimeter = std::max(perimeter, 2.0 * (r.width + r.height));
      }
      for (size_t i = 0; i < areas.size(); ++i) CHECK(std::fabs(areas[i] - twin_areas[i]) <= q * perimeter);
      CHECK(std::fabs(area - turned.area()) <= q * perimeter * blocks.size());
      ++turned_faces;
    }
  }
  CHECK(turned_faces == 48);
}

TEST_CASE("faces with a slanted edge have no rectilinear frame", "[region][frame]") {
  CHECK_FALSE(rectilinear_frame(Region(Ring{{0, 0}, {4, 0}, {4, 3}, {1, 4}, {0, 4}}, {}, 1e-7)));
  const auto frame = rectilinear_frame(Region(Ring{{0, 0}, {3, 4}, {-1, 7}, {-4, 3}}, {}, 1e-7));  // a turned rectangle
  REQUIRE(frame);
  CHECK(frame->angle == Approx(std::atan2(4.0, 3.0)));
}
