#include "core/env/decomposition.h"

#include <chrono>

#include "core/baselines/min_rectangles.h"

namespace autoblock {

Decomposition decompose_face(const GridFace& face, Policy& policy, EpisodeOptions options) {
  const auto start = std::chrono::steady_clock::now();
  Episode episode(face, options);
  Decomposition result;
  while (episode.running()) {
    episode.step(policy.choose(episode));
    result.decided_by.push_back(policy.decided_by());
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.policy = policy.name();
  result.reward = options.reward;
  for (const Piece& block : episode.blocks()) result.blocks.push_back(block.part.bbox());
  for (const Piece& piece : episode.queue()) result.unfinished.push_back(piece.part);
  result.cuts = episode.cuts();
  result.total_return = episode.total_return();
  result.status = episode.status();
  result.min_blocks = min_rectangles(face.whole);
  result.time_capped = policy.time_capped();
  return result;
}

}  // namespace autoblock
