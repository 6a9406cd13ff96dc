#include "core/env/reward.h"

#include <cmath>

#include "core/common/error.h"

namespace autoblock {

std::string reward_preset_name(RewardPreset preset) { return preset == RewardPreset::Paper ? "paper" : "mesh"; }

RewardPreset reward_preset_by_name(const std::string& name) {
  if (name == "paper") return RewardPreset::Paper;
  if (name == "mesh") return RewardPreset::Mesh;
  throw InputError("unknown reward preset '" + name + "' (expected paper or mesh)");
}

double equation_one(const std::vector<double>& areas, const std::vector<double>& aspect_ratios, int blocks) {
  const double n = static_cast<double>(areas.size());
  double sum_r2 = 0.0, sum_a = 0.0;
  for (size_t i = 0; i < areas.size(); ++i) {
    sum_r2 += aspect_ratios[i] * aspect_ratios[i];
    sum_a += areas[i];
  }
  const double mean_a = sum_a / n;
  double spread = 0.0;
  for (double a : areas) spread += (a - mean_a) * (a - mean_a);
  const double penalty = areas.size() == 1 ? 1.0 : 0.0;
  return 3.0 * (std::sqrt(n / sum_r2) - std::sqrt(spread / sum_a)) + 10.0 * blocks / n - 5.0 * penalty - 1.0;
}

double paper_reward(const std::vector<Part>& pieces, double face_size) {
  const double scale = 1.0 / (face_size * face_size);
  std::vector<double> areas, ratios;
  areas.reserve(pieces.size());
  ratios.reserve(pieces.size());
  int rectangles = 0;
  for (const Part& piece : pieces) {
    areas.push_back(piece.area() * scale);
    ratios.push_back(piece.bbox().aspect_ratio());
    if (piece.is_rectangle()) ++rectangles;
  }
  return equation_one(areas, ratios, rectangles);
}

double mesh_reward(const std::vector<Part>& pieces) {
  if (pieces.size() == 1) return -3.0;
  double thin = 0.0;
  for (const Part& piece : pieces) {
    if (piece.is_rectangle()) thin += std::log(piece.bbox().aspect_ratio());
  }
  return -static_cast<double>(pieces.size() - 1) - kMeshThinWeight * thin;
}

double cut_reward(RewardPreset preset, const std::vector<Part>& pieces, double face_size) {
  return preset == RewardPreset::Paper ? paper_reward(pieces, face_size) : mesh_reward(pieces);
}

}  // namespace autoblock
