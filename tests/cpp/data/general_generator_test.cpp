// The general face generator: every face it draws is a valid general face.
#include "core/data/general_generator.h"

#include <random>

#include <catch2/catch.hpp>

#include "core/region/validate_region.h"

using namespace autoblock;

TEST_CASE("generated general faces are simple, with their holes inside, at every vertex count", "[data][general]") {
  // Many vertices make wide angular gaps rare but possible: a star polygon is simple only when no gap
  // between consecutive angles reaches 180 degrees (a face with such a gap once crossed itself).
  std::mt19937_64 rng(20261130);
  for (int i = 0; i < 3000; ++i) {
    GeneralOptions options;
    options.kind = i % 5 == 4 ? GeneralKind::Chamfered : GeneralKind::Polygon;
    options.min_vertices = 3 + i % 10;
    options.max_vertices = options.min_vertices + i % 31;
    options.holes = i % 4 == 0;
    const GeneralShape shape = generate_general_shape(rng, options);
    std::vector<RawRing> rings{RawRing{"outer", shape.outer}};
    for (const Ring& h : shape.holes) rings.push_back(RawRing{"hole", h});
    INFO("face " << i << ": " << general_kind_name(options.kind) << ", " << shape.outer.size() << " vertices");
    CHECK_NOTHROW(validate_general_rings(rings));
  }
}
