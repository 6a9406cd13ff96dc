#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/data/thin_features.h"
#include "core/geometry/validate_polygon.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {
std::vector<RawRing> raw(const RectilinearPolygon& p) {
  std::vector<RawRing> rings{{"outer wire", p.outer}};
  for (const Ring& h : p.holes) rings.push_back({"inner wire", h});
  return rings;
}
}  // namespace

TEST_CASE("the generator is reproducible from its seed", "[data]") {
  const auto a = test::generated_shapes(10, 77, {});
  const auto b = test::generated_shapes(10, 77, {});
  for (size_t k = 0; k < a.size(); ++k) {
    REQUIRE(a[k].polygon.outer.size() == b[k].polygon.outer.size());
    for (size_t v = 0; v < a[k].polygon.outer.size(); ++v) CHECK(a[k].polygon.outer[v] == b[k].polygon.outer[v]);
  }
}

TEST_CASE("generated shapes are valid, non-rectangular unions of 2 to 10 rectangles", "[data]") {
  for (const GeneratedShape& shape : test::generated_shapes(200, 5, {})) {
    CHECK(shape.rectangles >= 2);
    CHECK(shape.rectangles <= 10);
    CHECK(shape.polygon.holes.empty());
    CHECK(shape.polygon.outer.size() > 4);
    const RectilinearPolygon checked = validate_rings(raw(shape.polygon));
    CHECK(polygon_area(checked) == Approx(polygon_area(shape.polygon)));
  }
}

TEST_CASE("with holes every generated shape has one", "[data]") {
  GeneratorOptions options;
  options.holes = true;
  options.min_rects = 11;
  options.max_rects = 40;
  for (const GeneratedShape& shape : test::generated_shapes(50, 6, options)) {
    CHECK(!shape.polygon.holes.empty());
    CHECK(shape.rectangles >= 11);
    CHECK_NOTHROW(validate_rings(raw(shape.polygon)));
  }
}

TEST_CASE("the generator rejects impossible options", "[data][errors]") {
  std::mt19937_64 rng(1);
  GeneratorOptions options;
  options.min_rects = 5;
  options.max_rects = 3;
  CHECK_THROWS_AS(generate_shape(rng, options), InputError);
  options.min_rects = options.max_rects = 1;
  CHECK_THROWS_AS(generate_shape(rng, options), InputError);
}

TEST_CASE("on a bounded grid, generated shapes stay inside it and have thin features", "[data]") {
  const GeneratorOptions options = thin_feature_options(2, 10);
  int unit_wide = 0;
  for (const GeneratedShape& shape : test::generated_shapes(100, 12, options)) {
    CHECK(shape.rectangles >= 2);
    CHECK(shape.rectangles <= 10);
    CHECK_NOTHROW(validate_rings(raw(shape.polygon)));
    double width = 0, height = 0;
    for (const Point2& p : shape.polygon.outer) {
      CHECK(p.x >= 0);
      CHECK(p.y >= 0);
      width = std::max(width, p.x);
      height = std::max(height, p.y);
    }
    CHECK(width <= 32);
    CHECK(height <= 32);
    // A boundary edge one unit long: the mark of a feature one unit wide.
    const Ring& ring = shape.polygon.outer;
    for (size_t k = 0; k < ring.size(); ++k) {
      const Point2 a = ring[k], b = ring[(k + 1) % ring.size()];
      if (std::abs(a.x - b.x) + std::abs(a.y - b.y) == 1) {
        ++unit_wide;
        break;
      }
    }
  }
  CHECK(unit_wide >= 30);
}

TEST_CASE("a grid smaller than the longest side is refused", "[data][errors]") {
  std::mt19937_64 rng(1);
  GeneratorOptions options;
  options.grid = 10;
  options.max_side = 12;
  CHECK_THROWS_AS(generate_shape(rng, options), InputError);
  options.grid = -1;
  CHECK_THROWS_AS(generate_shape(rng, options), InputError);
  options.grid = 12;
  CHECK_NOTHROW(generate_shape(rng, options));
}
