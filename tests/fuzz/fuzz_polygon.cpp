// libFuzzer target: the polygon checks and the grid engine's cuts, directly. The input bytes choose
// rings (an outer boundary and holes) as rectilinear walks with a scale from 1e-300 to 1e300,
// offsets near the tolerance, and now and then an arbitrary coordinate (NaN, infinities, huge).
//
// Properties checked (a violation aborts, which libFuzzer reports):
//   - validate_rings either throws InputError or returns a polygon whose area is positive;
//   - every cut of the whole part keeps the area (the pieces' areas sum to the part's);
//   - the greedy decomposition of an accepted face ends, and its blocks' areas sum to the face's.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "core/baselines/greedy_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/geometry/axis_cut.h"
#include "core/geometry/grid_face.h"
#include "core/geometry/validate_polygon.h"

namespace {

using namespace autoblock;

void require(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "property violated: %s\n", what);
    std::abort();
  }
}

bool close(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::max({1.0, std::fabs(a), std::fabs(b)}); }

double odd_value(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 5)) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return -std::numeric_limits<double>::max();
    case 3: return std::numeric_limits<double>::denorm_min();
    case 4: return in.ConsumeFloatingPoint<double>();
    default: return 0.0;
  }
}

RawRing ring_of(FuzzedDataProvider& in, double scale, double ox, double oy, int number) {
  RawRing ring;
  ring.name = number == 0 ? "outer wire" : "inner wire " + std::to_string(number);
  double x = ox, y = oy;
  const int turns = in.ConsumeIntegralInRange<int>(2, 24);
  for (int t = 0; t < turns; ++t) {
    ring.points.push_back({x, y});
    // Mostly rectilinear steps; sometimes a wobble near the tolerance or an odd coordinate.
    const double step = scale * in.ConsumeIntegralInRange<int>(-12, 12);
    const double wobble = in.ConsumeBool() ? scale * 1e-7 * in.ConsumeIntegralInRange<int>(-20, 20) : 0.0;
    if (t % 2 == 0) {
      x += step;
      y += wobble;
    } else {
      y += step;
      x += wobble;
    }
    if (in.ConsumeIntegralInRange<int>(0, 40) == 0) (in.ConsumeBool() ? x : y) = odd_value(in);
  }
  // Close the walk rectilinearly: back to the start's x, then its y.
  ring.points.push_back({x, y});
  ring.points.push_back({ox, y});
  return ring;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  static const double scales[] = {1e-300, 1e-9, 1e-6, 1e-3, 1.0, 7.0, 1e3, 1e6, 1e12, 1e300};
  const double scale = scales[in.ConsumeIntegralInRange<int>(0, 9)];
  std::vector<RawRing> rings;
  const int count = in.ConsumeIntegralInRange<int>(1, 4);
  for (int r = 0; r < count && in.remaining_bytes() > 0; ++r) {
    const double ox = scale * in.ConsumeIntegralInRange<int>(-8, 8), oy = scale * in.ConsumeIntegralInRange<int>(-8, 8);
    rings.push_back(ring_of(in, scale, ox, oy, r));
  }
  RectilinearPolygon polygon;
  GridFace face;
  try {
    polygon = validate_rings(rings);
    face = make_grid_face(polygon);
  } catch (const InputError&) {
    return 0;
  }
  const double area = polygon_area(polygon);
  if (!(area > 0 && std::isfinite(area))) std::fprintf(stderr, "scale %g, area %g\n", scale, area);
  require(area > 0 && std::isfinite(area), "an accepted polygon has a positive finite area");
  require(close(face.whole.area(), area), "the grid part's area is the polygon's");

  const Grid& grid = face.whole.grid();
  for (int k = 0; k < 4 && in.remaining_bytes() > 0; ++k) {
    AxisLine line;
    line.direction = in.ConsumeBool() ? CutDirection::Horizontal : CutDirection::Vertical;
    const int lines = static_cast<int>(line.direction == CutDirection::Horizontal ? grid.ys.size() : grid.xs.size());
    line.index = in.ConsumeIntegralInRange<int>(0, lines - 1);
    double total = 0.0;
    const std::vector<Part> pieces = cut_part(face.whole, line);
    for (const Part& piece : pieces) total += piece.area();
    require(close(total, face.whole.area()), "a cut keeps the area");
    require((pieces.size() > 1) == line_crosses_interior(face.whole, line), "a cut splits exactly when it crosses");
  }

  GreedyPolicy greedy;
  const Decomposition result = decompose_face(face, greedy, {});
  if (result.complete()) {
    double blocks = 0.0;
    for (const Box& b : result.blocks) blocks += (b.xmax - b.xmin) * (b.ymax - b.ymin);
    require(close(blocks, area), "the blocks cover the face's area");
  }
  return 0;
}
