#include "core/sac/part_lookahead.h"

#include <cmath>
#include <map>
#include <utility>

namespace autoblock {

double lookahead_reward_scale(RewardPreset preset) { return preset == RewardPreset::Paper ? 10.0 : 1.0; }

PartLookahead look_ahead(const Part& part, const std::vector<CornerRing>& loops, double face_size, RewardPreset preset) {
  PartLookahead result;
  const double scale = lookahead_reward_scale(preset);
  // Each line is cut once; its summary is shared by the corners on it.
  std::map<std::pair<int, int>, std::array<float, 3>> summary;
  int vertex = 0;
  for (const CornerRing& loop : loops) {
    for (const Corner& corner : loop) {
      std::array<float, kVertexLookahead> f{};
      f[0] = corner.reflex ? 1.0f : 0.0f;
      for (int d = 0; d < 2; ++d) {
        const CutDirection direction = static_cast<CutDirection>(d);
        const AxisLine line{direction, direction == CutDirection::Vertical ? corner.i : corner.j};
        const auto key = std::make_pair(d, line.index);
        auto found = summary.find(key);
        if (found == summary.end()) {
          const std::vector<Part> pieces = cut_part(part, line);
          LineCandidate candidate;
          candidate.line = line;
          candidate.vertex = vertex;
          candidate.reward = cut_reward(preset, pieces, face_size);
          candidate.pieces = static_cast<int>(pieces.size());
          for (const Part& piece : pieces) {
            if (piece.is_rectangle()) {
              ++candidate.rectangles;
            } else {
              candidate.to_cut.push_back(piece);
            }
          }
          found = summary
                      .emplace(key, std::array<float, 3>{static_cast<float>(candidate.reward / scale),
                                                         static_cast<float>(candidate.pieces) / 4.0f,
                                                         static_cast<float>(candidate.rectangles) / static_cast<float>(candidate.pieces)})
                      .first;
          if (candidate.pieces > 1) result.lines.push_back(std::move(candidate));
        }
        f[static_cast<size_t>(1 + d)] = found->second[0];
        f[static_cast<size_t>(3 + d)] = found->second[1];
        f[static_cast<size_t>(5 + d)] = found->second[2];
      }
      result.vertex_features.push_back(f);
      ++vertex;
    }
  }
  result.scale = {static_cast<float>(part.bbox().longer_side() / face_size),
                  static_cast<float>(std::sqrt(part.area()) / face_size)};
  return result;
}

}  // namespace autoblock
