#include "core/geometry/axis_cut.h"

#include <utility>

namespace autoblock {

std::string direction_name(CutDirection direction) {
  return direction == CutDirection::Horizontal ? "horizontal" : "vertical";
}

bool line_crosses_interior(const Part& part, const AxisLine& line) {
  const int k = line.index;
  if (line.direction == CutDirection::Vertical) {
    if (k <= part.i0() || k >= part.i0() + part.width_cells()) return false;
    for (int j = part.j0(); j < part.j0() + part.height_cells(); ++j) {
      if (part.contains(k - 1, j) && part.contains(k, j)) return true;
    }
  } else {
    if (k <= part.j0() || k >= part.j0() + part.height_cells()) return false;
    for (int i = part.i0(); i < part.i0() + part.width_cells(); ++i) {
      if (part.contains(i, k - 1) && part.contains(i, k)) return true;
    }
  }
  return false;
}

std::vector<Part> cut_part(const Part& part, const AxisLine& line) {
  if (!line_crosses_interior(part, line)) return {part};
  const int w = part.width_cells(), h = part.height_cells();
  const int i0 = part.i0(), j0 = part.j0();
  const bool vertical = line.direction == CutDirection::Vertical;
  // Flood fill over the window with 4-neighbours, never stepping across the line.
  std::vector<int> label(static_cast<size_t>(w * h), -1);
  std::vector<Part> pieces;
  std::vector<std::pair<int, int>> stack, cells;
  for (int b = 0; b < h; ++b) {
    for (int a = 0; a < w; ++a) {
      if (label[static_cast<size_t>(b * w + a)] != -1 || !part.contains(i0 + a, j0 + b)) continue;
      const int id = static_cast<int>(pieces.size());
      cells.clear();
      stack.assign(1, {a, b});
      label[static_cast<size_t>(b * w + a)] = id;
      while (!stack.empty()) {
        const auto [ca, cb] = stack.back();
        stack.pop_back();
        cells.emplace_back(i0 + ca, j0 + cb);
        const int next[4][2] = {{ca + 1, cb}, {ca - 1, cb}, {ca, cb + 1}, {ca, cb - 1}};
        for (const auto& n : next) {
          const int na = n[0], nb = n[1];
          if (na < 0 || nb < 0 || na >= w || nb >= h) continue;
          // Crossing between cells c and n happens across the grid line max(c, n).
          if (vertical && nb == cb && i0 + std::max(na, ca) == line.index) continue;
          if (!vertical && na == ca && j0 + std::max(nb, cb) == line.index) continue;
          int& slot = label[static_cast<size_t>(nb * w + na)];
          if (slot != -1 || !part.contains(i0 + na, j0 + nb)) continue;
          slot = id;
          stack.emplace_back(na, nb);
        }
      }
      pieces.emplace_back(part.grid_ptr(), cells);
    }
  }
  return pieces;
}

}  // namespace autoblock
