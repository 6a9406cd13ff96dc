#include "core/geometry/grid_face.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {
namespace {

std::vector<double> sorted_unique(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

int index_of(const std::vector<double>& values, double v) {
  return static_cast<int>(std::lower_bound(values.begin(), values.end(), v) - values.begin());
}

}  // namespace

GridFace make_grid_face(const RectilinearPolygon& polygon) {
  std::vector<const Ring*> rings{&polygon.outer};
  for (const Ring& hole : polygon.holes) rings.push_back(&hole);
  std::vector<double> xs, ys;
  size_t corner_count = 0;
  for (const Ring* ring : rings) {
    for (const Point2& p : *ring) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
    corner_count += ring->size();
  }
  auto grid = std::make_shared<Grid>();
  grid->xs = sorted_unique(xs);
  grid->ys = sorted_unique(ys);
  const long cells = static_cast<long>(grid->columns()) * grid->rows();
  if (cells > kMaxGridCells) {
    throw InputError("the face is too complex: its " + std::to_string(grid->xs.size()) + " x " +
                     std::to_string(grid->ys.size()) + " distinct corner coordinates exceed the limit of " +
                     std::to_string(kMaxGridCells) + " grid cells");
  }
  // Even-odd fill, row by row: the vertical edges crossing the row's middle toggle inside/outside.
  std::vector<std::pair<int, int>> inside;
  std::vector<int> crossings;
  for (int j = 0; j < grid->rows(); ++j) {
    const double yc = 0.5 * (grid->ys[static_cast<size_t>(j)] + grid->ys[static_cast<size_t>(j) + 1]);
    crossings.clear();
    for (const Ring* ring : rings) {
      const size_t n = ring->size();
      for (size_t k = 0; k < n; ++k) {
        const Point2& a = (*ring)[k];
        const Point2& b = (*ring)[(k + 1) % n];
        if (a.x == b.x && (a.y < yc) != (b.y < yc)) crossings.push_back(index_of(grid->xs, a.x));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (size_t c = 0; c + 1 < crossings.size(); c += 2) {
      for (int i = crossings[c]; i < crossings[c + 1]; ++i) inside.emplace_back(i, j);
    }
  }
  GridFace face;
  face.grid = grid;
  face.whole = Part(grid, inside);
  face.size = face.whole.bbox().longer_side();
  // The cells must reproduce the polygon exactly: same loops, same corners.
  const auto loops = part_boundary(face.whole);
  size_t traced = 0;
  for (const auto& loop : loops) traced += loop.size();
  if (loops.size() != rings.size() || traced != corner_count) {
    throw std::logic_error("make_grid_face: the grid does not reproduce the polygon");
  }
  return face;
}

}  // namespace autoblock
