#include "core/env/reward.h"

#include <cmath>

namespace autoblock {

double paper_reward(const std::vector<Part>& pieces, double face_size) {
  const double n = static_cast<double>(pieces.size());
  const double scale = 1.0 / (face_size * face_size);
  double sum_r2 = 0.0, sum_a = 0.0;
  int rectangles = 0;
  for (const Part& piece : pieces) {
    const double r = piece.bbox().aspect_ratio();
    sum_r2 += r * r;
    sum_a += piece.area() * scale;
    if (piece.is_rectangle()) ++rectangles;
  }
  const double mean_a = sum_a / n;
  double spread = 0.0;
  for (const Part& piece : pieces) {
    const double d = piece.area() * scale - mean_a;
    spread += d * d;
  }
  const double penalty = pieces.size() == 1 ? 1.0 : 0.0;
  return 3.0 * (std::sqrt(n / sum_r2) - std::sqrt(spread / sum_a)) + 10.0 * rectangles / n - 5.0 * penalty - 1.0;
}

}  // namespace autoblock
