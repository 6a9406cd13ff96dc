// Order statistics for the benchmarks' tables.
#pragma once

#include <algorithm>
#include <vector>

namespace autoblock::bench {

// Inputs: values; q in [0, 1]. Output: the q-quantile, linearly interpolated (0 when empty).
inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const double position = q * static_cast<double>(v.size() - 1);
  const auto low = static_cast<size_t>(position);
  const size_t high = std::min(low + 1, v.size() - 1);
  return v[low] + (position - static_cast<double>(low)) * (v[high] - v[low]);
}

}  // namespace autoblock::bench
