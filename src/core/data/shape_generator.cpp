#include "core/data/shape_generator.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/geometry/grid.h"
#include "core/geometry/part.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {
namespace {

struct IntRect {
  int x, y, w, h;
};

// A bitmap of unit cells over [0, width) x [0, height).
struct Bitmap {
  int width = 0, height = 0;
  std::vector<char> cells;
  bool at(int i, int j) const {
    return i >= 0 && j >= 0 && i < width && j < height && cells[static_cast<size_t>(j * width + i)];
  }
  void set(int i, int j, char v) { cells[static_cast<size_t>(j * width + i)] = v; }
};

// The loops of a bitmap's cells as a polygon, or false when the cells are not one valid region.
bool bitmap_polygon(const Bitmap& bitmap, RectilinearPolygon* polygon, bool* is_rectangle) {
  auto grid = std::make_shared<Grid>();
  for (int i = 0; i <= bitmap.width; ++i) grid->xs.push_back(i);
  for (int j = 0; j <= bitmap.height; ++j) grid->ys.push_back(j);
  std::vector<std::pair<int, int>> cells;
  for (int j = 0; j < bitmap.height; ++j) {
    for (int i = 0; i < bitmap.width; ++i) {
      if (bitmap.at(i, j)) cells.emplace_back(i, j);
    }
  }
  const Part part(grid, cells);
  std::vector<CornerRing> loops;
  try {
    loops = part_boundary(part);  // throws where the boundary touches itself
  } catch (const std::logic_error&) {
    return false;
  }
  *is_rectangle = part.is_rectangle();
  polygon->outer.clear();
  polygon->holes.clear();
  for (size_t l = 0; l < loops.size(); ++l) {
    Ring ring;
    for (const Corner& c : loops[l]) ring.push_back(Point2{static_cast<double>(c.i), static_cast<double>(c.j)});
    if (l == 0) {
      polygon->outer = ring;
    } else {
      polygon->holes.push_back(ring);
    }
  }
  return true;
}

int uniform(std::mt19937_64& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

// Punches a hole of 1-3 x 1-3 units whose one-unit margin lies wholly inside the region.
bool punch_hole(std::mt19937_64& rng, Bitmap& bitmap) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int w = uniform(rng, 1, 3), h = uniform(rng, 1, 3);
    if (w + 2 > bitmap.width || h + 2 > bitmap.height) return false;
    const int x = uniform(rng, 1, bitmap.width - w - 1), y = uniform(rng, 1, bitmap.height - h - 1);
    bool fits = true;
    for (int j = y - 1; fits && j <= y + h; ++j) {
      for (int i = x - 1; fits && i <= x + w; ++i) fits = bitmap.at(i, j);
    }
    if (!fits) continue;
    for (int j = y; j < y + h; ++j) {
      for (int i = x; i < x + w; ++i) bitmap.set(i, j, 0);
    }
    return true;
  }
  return false;
}

}  // namespace

GeneratedShape generate_shape(std::mt19937_64& rng, const GeneratorOptions& options) {
  if (options.min_rects < 1 || options.max_rects < options.min_rects) {
    throw InputError("the number of rectangles must satisfy 1 <= min <= max (got " +
                     std::to_string(options.min_rects) + " and " + std::to_string(options.max_rects) + ")");
  }
  if (options.min_side < 1 || options.max_side < options.min_side) {
    throw InputError("rectangle sides must satisfy 1 <= min <= max (got " + std::to_string(options.min_side) +
                     " and " + std::to_string(options.max_side) + ")");
  }
  if (options.grid < 0 || (options.grid > 0 && options.grid < options.max_side)) {
    throw InputError("the grid must be 0 (unbounded) or at least the longest side (got grid " +
                     std::to_string(options.grid) + ", longest side " + std::to_string(options.max_side) + ")");
  }
  if (options.max_rects == 1 && !options.holes) {
    throw InputError("one rectangle is always a rectangle: ask for at least 2");
  }
  for (int attempt = 0; attempt < 100000; ++attempt) {
    const int k = uniform(rng, options.min_rects, options.max_rects);
    const int grid = options.grid;
    std::vector<IntRect> rects;
    IntRect first{0, 0, uniform(rng, options.min_side, options.max_side), uniform(rng, options.min_side, options.max_side)};
    if (grid > 0) {
      first.x = uniform(rng, 0, grid - first.w);
      first.y = uniform(rng, 0, grid - first.h);
    }
    rects.push_back(first);
    while (static_cast<int>(rects.size()) < k) {
      const IntRect& anchor = rects[static_cast<size_t>(uniform(rng, 0, static_cast<int>(rects.size()) - 1))];
      IntRect r{0, 0, uniform(rng, options.min_side, options.max_side), uniform(rng, options.min_side, options.max_side)};
      // Positive-area overlap with the anchor (and, on a grid, inside it: the ranges are never
      // empty because the anchor is inside it).
      const int x_low = anchor.x - r.w + 1, x_high = anchor.x + anchor.w - 1;
      const int y_low = anchor.y - r.h + 1, y_high = anchor.y + anchor.h - 1;
      r.x = grid > 0 ? uniform(rng, std::max(x_low, 0), std::min(x_high, grid - r.w)) : uniform(rng, x_low, x_high);
      r.y = grid > 0 ? uniform(rng, std::max(y_low, 0), std::min(y_high, grid - r.h)) : uniform(rng, y_low, y_high);
      rects.push_back(r);
    }
    int x0 = rects[0].x, y0 = rects[0].y, x1 = x0, y1 = y0;
    for (const IntRect& r : rects) {
      x0 = std::min(x0, r.x);
      y0 = std::min(y0, r.y);
      x1 = std::max(x1, r.x + r.w);
      y1 = std::max(y1, r.y + r.h);
    }
    Bitmap bitmap{x1 - x0, y1 - y0, {}};
    bitmap.cells.assign(static_cast<size_t>(bitmap.width * bitmap.height), 0);
    for (const IntRect& r : rects) {
      for (int j = r.y - y0; j < r.y - y0 + r.h; ++j) {
        for (int i = r.x - x0; i < r.x - x0 + r.w; ++i) bitmap.set(i, j, 1);
      }
    }
    GeneratedShape shape;
    shape.rectangles = k;
    bool rectangle = false;
    if (!bitmap_polygon(bitmap, &shape.polygon, &rectangle)) continue;
    if (options.holes && shape.polygon.holes.empty()) {
      const int wanted = uniform(rng, 1, 2);
      for (int h = 0; h < wanted; ++h) punch_hole(rng, bitmap);
      if (!bitmap_polygon(bitmap, &shape.polygon, &rectangle) || shape.polygon.holes.empty()) continue;
    }
    if (!options.holes && !shape.polygon.holes.empty()) continue;
    if (rectangle) continue;
    return shape;
  }
  throw std::runtime_error("generate_shape: no valid shape after 100000 attempts");
}

}  // namespace autoblock
