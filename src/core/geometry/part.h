// A part of a face: a connected set of cells of the face's grid (see grid.h).
//
// Stored as the tight window of cells it occupies plus one bit per window cell. Parts are values:
// cheap to copy (the grid is shared), comparable and hashable, so a search can memoise on them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/geometry/grid.h"
#include "core/geometry/point.h"

namespace autoblock {

class Part {
 public:
  Part() = default;
  // Inputs: grid; cells, the (column, row) indices of the part's cells (any order, no repeats).
  Part(std::shared_ptr<const Grid> grid, const std::vector<std::pair<int, int>>& cells);

  const Grid& grid() const { return *grid_; }
  const std::shared_ptr<const Grid>& grid_ptr() const { return grid_; }

  // Window of cells: columns [i0, i0 + width), rows [j0, j0 + height).
  int i0() const { return i0_; }
  int j0() const { return j0_; }
  int width_cells() const { return w_; }
  int height_cells() const { return h_; }

  // Inputs: global cell indices. Output: true when the cell belongs to the part.
  bool contains(int i, int j) const {
    const int a = i - i0_, b = j - j0_;
    if (a < 0 || b < 0 || a >= w_ || b >= h_) return false;
    const size_t k = static_cast<size_t>(b * w_ + a);
    return (bits_[k >> 6] >> (k & 63)) & 1u;
  }

  int cell_count() const { return count_; }
  // A rectangle is a part that fills its bounding box (exactly four corners).
  bool is_rectangle() const { return count_ == w_ * h_; }
  double area() const { return area_; }
  Point2 centroid() const { return centroid_; }
  Box bbox() const;

  bool operator==(const Part& other) const;
  size_t hash() const;

 private:
  std::shared_ptr<const Grid> grid_;
  int i0_ = 0, j0_ = 0, w_ = 0, h_ = 0, count_ = 0;
  double area_ = 0.0;
  Point2 centroid_;
  std::vector<std::uint64_t> bits_;
};

struct PartHash {
  size_t operator()(const Part& part) const { return part.hash(); }
};

}  // namespace autoblock
