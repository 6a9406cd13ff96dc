#include "core/geometry/part_symmetry.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace autoblock {
namespace {

// One step: mirror x (x -> -x) or a quarter turn ((x, y) -> (-y, x)).
std::pair<std::shared_ptr<Grid>, std::vector<std::pair<int, int>>> apply(const Grid& grid,
                                                                          std::vector<std::pair<int, int>> cells,
                                                                          bool mirror) {
  auto next = std::make_shared<Grid>();
  const int columns = grid.columns(), rows = grid.rows();
  if (mirror) {
    for (auto it = grid.xs.rbegin(); it != grid.xs.rend(); ++it) next->xs.push_back(-*it);
    next->ys = grid.ys;
    for (auto& [i, j] : cells) i = columns - 1 - i;
  } else {
    for (auto it = grid.ys.rbegin(); it != grid.ys.rend(); ++it) next->xs.push_back(-*it);
    next->ys = grid.xs;
    for (auto& [i, j] : cells) {
      const int ni = rows - 1 - j, nj = i;
      i = ni;
      j = nj;
    }
  }
  return {next, cells};
}

}  // namespace

Part transform_part(const Part& part, int symmetry) {
  if (symmetry < 0 || symmetry > 7) throw std::logic_error("transform_part: symmetry must be in 0..7");
  std::vector<std::pair<int, int>> cells;
  for (int j = part.j0(); j < part.j0() + part.height_cells(); ++j) {
    for (int i = part.i0(); i < part.i0() + part.width_cells(); ++i) {
      if (part.contains(i, j)) cells.emplace_back(i, j);
    }
  }
  std::shared_ptr<const Grid> grid = part.grid_ptr();
  if (symmetry & 1) {
    auto [g, c] = apply(*grid, cells, true);
    grid = g;
    cells = c;
  }
  for (int turn = 0; turn < (symmetry >> 1); ++turn) {
    auto [g, c] = apply(*grid, cells, false);
    grid = g;
    cells = c;
  }
  return Part(grid, cells);
}

}  // namespace autoblock
