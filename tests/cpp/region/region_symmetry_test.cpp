#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/region/region_policy.h"
#include "core/region/region_symmetry.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("a turned or mirrored part keeps its area, vertices, blocks and best rewards", "[region][symmetry]") {
  const auto lock = lock_general_engine();
  for (int k = 0; k < 6; ++k) {
    const Region part = test::region_of(test::general_polygon(1400 + k, k % 2 ? GeneralKind::Chamfered : GeneralKind::Polygon, k % 3 == 0));
    const double size = part.bbox().longer_side();
    RegionEpisodeOptions options;
    options.reward = RewardPreset::Mesh;
    options.rules = mesh_block_rules(part.loops());
    CHECK(transform_region(part, 0.0, false) == part);
    CHECK(transform_region(transform_region(part, 0.0, true), 0.0, true) == part);  // a mirror on the lattice
    std::vector<ScoredAction> before = score_candidates(part, size, options);
    REQUIRE(!before.empty());
    for (const double angle : {0.3, 1.9, 4.0}) {
      for (const bool mirror : {false, true}) {
        INFO("face " << k << ", angle " << angle << ", mirror " << mirror);
        const Region view = transform_region(part, angle, mirror);
        CHECK(view.area() == Approx(part.area()).epsilon(1e-6));
        CHECK(view.vertex_count() == part.vertex_count());
        CHECK(view.holes().size() == part.holes().size());
        CHECK(view.quantum() == part.quantum());
        // The best rewards do not depend on the frame (the face's size and rules kept).
        std::vector<ScoredAction> after = score_candidates(view, size, options);
        REQUIRE(!after.empty());
        auto best = [](const std::vector<ScoredAction>& s) {
          double b = -1e300;
          for (const ScoredAction& a : s) b = std::max(b, a.reward);
          return b;
        };
        CHECK(best(after) == Approx(best(before)).margin(1e-3));
      }
    }
  }
}
