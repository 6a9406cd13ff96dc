// The coordinate grid of a face: the distinct x and y coordinates of its corners, increasing.
//
// Every cut runs through a corner along X or Y, so every part and block of a decomposition has its
// corners on this grid: parts are exact sets of grid cells (see part.h). Cell (i, j) is
// [xs[i], xs[i+1]] x [ys[j], ys[j+1]]; grid point (i, j) is (xs[i], ys[j]).
#pragma once

#include <vector>

namespace autoblock {

struct Grid {
  std::vector<double> xs;
  std::vector<double> ys;

  int columns() const { return static_cast<int>(xs.size()) - 1; }
  int rows() const { return static_cast<int>(ys.size()) - 1; }
  double cell_width(int i) const { return xs[static_cast<size_t>(i) + 1] - xs[static_cast<size_t>(i)]; }
  double cell_height(int j) const { return ys[static_cast<size_t>(j) + 1] - ys[static_cast<size_t>(j)]; }
};

}  // namespace autoblock
