// Random test shapes like the paper's: connected unions of k axis-aligned rectangles.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

struct GeneratorOptions {
  int min_rects = 2;
  int max_rects = 10;
  bool holes = false;  // false: every shape simply connected; true: every shape has 1 or 2 holes
  int min_side = 2;    // rectangle sides are integers in [min_side, max_side]
  int max_side = 12;
  // 0: rectangles are placed anywhere (each overlapping an earlier one); G > 0: every rectangle
  // lies inside a G x G square, so unions crowd and features one unit wide are common (thin
  // features: e.g. grid 32 with sides 3-18, or grid 64 with sides 4-24). Needs max_side <= G.
  int grid = 0;
};

struct GeneratedShape {
  RectilinearPolygon polygon;  // integer coordinates, bounding box starting at (0, 0)
  int rectangles = 0;          // k, the number of rectangles united
};

// Inputs:  rng; options (1 <= min_rects <= max_rects, 1 <= min_side <= max_side, grid 0 or
//          >= max_side).
// Outputs: one shape: k ~ uniform[min_rects, max_rects] rectangles, each new one overlapping an
//          earlier one with positive area; unions that are a plain rectangle or whose boundary
//          touches itself are drawn again. With holes, rectangular holes with a margin of at least
//          one unit are punched when the union has none of its own. With grid > 0 every
//          rectangle lies in [0, grid]^2 (the shape's bounding box is then moved to (0, 0)).
// Throws InputError for invalid options.
GeneratedShape generate_shape(std::mt19937_64& rng, const GeneratorOptions& options);

}  // namespace autoblock
