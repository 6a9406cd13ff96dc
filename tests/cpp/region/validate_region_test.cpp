#include "core/region/validate_region.h"

#include <cmath>

#include <catch2/catch.hpp>

#include "core/common/error.h"

using namespace autoblock;

namespace {

std::string error_of(const std::vector<RawRing>& rings) {
  try {
    validate_general_rings(rings);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("general faces: slanted edges, any orientation, holes", "[region][validate]") {
  // A chamfered square drawn clockwise, with a turned square hole drawn clockwise too.
  const RawRing outer{"outer wire", {{0, 0}, {0, 8}, {9, 10}, {10, 0}}};
  const RawRing hole{"wire 2", {{4, 3}, {5, 4}, {6, 3}, {5, 2}}};
  double tol = 0.0;
  const Region region = validate_general_rings({hole, outer}, &tol);
  CHECK(tol == Approx(1e-6));
  CHECK(region.outer().size() == 4);
  CHECK(signed_area(region.outer()) > 0.0);
  REQUIRE(region.holes().size() == 1);
  CHECK(signed_area(region.holes()[0]) < 0.0);
  CHECK(region.area() == Approx(86.0 - 2.0));
  // A vertex between collinear edges is merged away.
  CHECK(validate_general_rings({{"outer wire", {{0, 0}, {2, 1}, {4, 2}, {0, 5}}}}).outer().size() == 3);
}

TEST_CASE("general faces: every bad input names the edge or corner and where it is", "[region][validate]") {
  // A bow tie crosses itself.
  const std::string bow = error_of({{"outer wire", {{0, 0}, {4, 4}, {4, 0}, {0, 4}}}});
  CHECK(bow.find("the outer wire crosses or touches itself") != std::string::npos);
  CHECK(bow.find("edge 1 from (0, 0) to (4, 4)") != std::string::npos);
  // A hole touching the outer wire.
  const std::string touch = error_of({{"outer wire", {{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, {"wire 2", {{0, 5}, {3, 4}, {3, 6}}}});
  CHECK(touch.find("the outer wire crosses or touches the wire 2") != std::string::npos);
  // A sliver: two edges closer than the tolerance.
  const std::string sliver =
      error_of({{"outer wire", {{0, 0}, {10, 0}, {10, 10}, {5, 1e-8}, {0, 10}}}});
  CHECK(sliver.find("comes within the tolerance of itself") != std::string::npos);
  // A sharp corner.
  const std::string sharp = error_of({{"outer wire", {{0, 0}, {10, 0}, {0, 0.5}}}});
  CHECK(sharp.find("corner of 2.86 degrees at (10, 0)") != std::string::npos);
  // A short edge, zero area, a hole outside, a hole in a hole.
  CHECK(error_of({{"outer wire", {{0, 0}, {10, 0}, {10, 10}, {10, 10 + 1e-7}, {0, 10}}}}).find("is shorter than the tolerance") !=
        std::string::npos);
  CHECK(error_of({{"outer wire", {{0, 0}, {10, 0}, {20, 0}}}}).find("zero or tiny area") != std::string::npos);
  CHECK(error_of({{"outer wire", {{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, {"wire 2", {{20, 20}, {21, 20}, {21, 21}}}})
            .find("lies outside the outer wire") != std::string::npos);
  CHECK(error_of({{"outer wire", {{0, 0}, {10, 0}, {10, 10}, {0, 10}}},
                  {"wire 2", {{2, 2}, {8, 2}, {8, 8}, {2, 8}}},
                  {"wire 3", {{4, 4}, {5, 4}, {5, 5}}}})
            .find("lies inside the hole bounded by the wire 2") != std::string::npos);
}
