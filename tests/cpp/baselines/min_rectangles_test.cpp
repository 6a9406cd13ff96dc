#include <catch2/catch.hpp>

#include "core/baselines/min_rectangles.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("minimum rectangles of hand-checked shapes", "[baselines][minrect]") {
  // L: 1 re-entrant corner, no chord: 1 - 0 - 0 + 1 = 2.
  CHECK(min_rectangles(test::grid_face_of(test::l_shape()).whole) == 2);
  // U: 2 re-entrant corners; the segment between them is an edge, not a chord: 3.
  CHECK(min_rectangles(test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}).whole) == 3);
  // H: 4 re-entrant corners, 2 disjoint vertical chords: 4 - 2 + 1 = 3.
  CHECK(min_rectangles(test::grid_face_of({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 2},
                                           {1, 2}, {1, 3}, {0, 3}})
                           .whole) == 3);
  // Plus: 4 re-entrant corners, 2 horizontal and 2 vertical chords, each horizontal meeting each
  // vertical at a corner: at most 2 disjoint, 4 - 2 + 1 = 3.
  CHECK(min_rectangles(test::grid_face_of({{1, 0}, {2, 0}, {2, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}, {1, 2},
                                           {0, 2}, {0, 1}, {1, 1}})
                           .whole) == 3);
  // A square with a hole: 4 re-entrant corners, no chord, 1 hole: 4 - 0 - 1 + 1 = 4.
  CHECK(min_rectangles(test::grid_face_of(test::square3(), {test::centre_hole()}).whole) == 4);
  // A rectangle: 1.
  CHECK(min_rectangles(test::grid_face_of(test::square3()).whole) == 1);
}

TEST_CASE("minimum rectangles of a C whose re-entrant corners share an edge", "[baselines][minrect]") {
  // (0,0) (3,0) (3,1) (2,1) (2,2) (3,2) (3,3) (0,3): re-entrant corners (2,1) and (2,2) are joined
  // by the notch's edge, which is boundary, not a chord: 2 - 0 + 1 = 3.
  CHECK(min_rectangles(test::grid_face_of({{0, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 2}, {3, 2}, {3, 3}, {0, 3}}).whole) == 3);
}
