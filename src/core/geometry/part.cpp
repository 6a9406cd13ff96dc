#include "core/geometry/part.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace autoblock {

Part::Part(std::shared_ptr<const Grid> grid, const std::vector<std::pair<int, int>>& cells)
    : grid_(std::move(grid)) {
  if (cells.empty()) throw std::logic_error("Part: no cells");
  int i1 = std::numeric_limits<int>::min(), j1 = i1;
  i0_ = j0_ = std::numeric_limits<int>::max();
  for (const auto& [i, j] : cells) {
    i0_ = std::min(i0_, i);
    j0_ = std::min(j0_, j);
    i1 = std::max(i1, i);
    j1 = std::max(j1, j);
  }
  w_ = i1 - i0_ + 1;
  h_ = j1 - j0_ + 1;
  bits_.assign((static_cast<size_t>(w_) * static_cast<size_t>(h_) + 63) / 64, 0);
  double mx = 0.0, my = 0.0;
  for (const auto& [i, j] : cells) {
    const size_t k = static_cast<size_t>((j - j0_) * w_ + (i - i0_));
    bits_[k >> 6] |= std::uint64_t{1} << (k & 63);
    const double a = grid_->cell_width(i) * grid_->cell_height(j);
    area_ += a;
    mx += a * 0.5 * (grid_->xs[static_cast<size_t>(i)] + grid_->xs[static_cast<size_t>(i) + 1]);
    my += a * 0.5 * (grid_->ys[static_cast<size_t>(j)] + grid_->ys[static_cast<size_t>(j) + 1]);
  }
  count_ = static_cast<int>(cells.size());
  centroid_ = Point2{mx / area_, my / area_};
}

Box Part::bbox() const {
  const auto& xs = grid_->xs;
  const auto& ys = grid_->ys;
  return Box{xs[static_cast<size_t>(i0_)], ys[static_cast<size_t>(j0_)], xs[static_cast<size_t>(i0_ + w_)],
             ys[static_cast<size_t>(j0_ + h_)]};
}

bool Part::operator==(const Part& other) const {
  return grid_ == other.grid_ && i0_ == other.i0_ && j0_ == other.j0_ && w_ == other.w_ && h_ == other.h_ &&
         bits_ == other.bits_;
}

size_t Part::hash() const {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  };
  mix(static_cast<std::uint64_t>(i0_) | (static_cast<std::uint64_t>(j0_) << 16) |
      (static_cast<std::uint64_t>(w_) << 32) | (static_cast<std::uint64_t>(h_) << 48));
  for (std::uint64_t word : bits_) mix(word);
  return static_cast<size_t>(h);
}

}  // namespace autoblock
