#include "core/sac/region_lookahead.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <utility>

#include "core/region/block.h"
#include "core/region/region_candidates.h"
#include "core/region/region_reward.h"

namespace autoblock {

RegionLookahead region_look_ahead(const Region& part, double face_size, const RegionEpisodeOptions& options, bool taper,
                                  SearchWork* work) {
  RegionLookahead result;
  const double scale = lookahead_reward_scale(options.reward);
  // The vertex each candidate starts at, by its origin (candidates start at a vertex exactly).
  std::map<std::pair<double, double>, int> vertex_at;
  std::vector<bool> reflex;
  for (const Ring& loop : part.loops()) {
    for (size_t i = 0; i < loop.size(); ++i) {
      vertex_at.emplace(std::make_pair(loop[i].x, loop[i].y), static_cast<int>(reflex.size()));
      reflex.push_back(vertex_shape(loop, i, options.rules).reflex);
    }
  }
  // What a cut separating nothing earns: the value of a missing cut in a vertex's summary.
  const double nothing = region_cut_reward(options.reward, CutOutcome{{part}, {}}, face_size, options.rules);
  std::vector<std::vector<size_t>> at_vertex(reflex.size());
  // As the search expands them whatever their reward (region_search.cpp): the O-grid on a part with a
  // hole, the template on a reflex fillet's corner piece.
  const bool finishing_template = !part.holes().empty() || !concave_runs(part.outer(), options.rules).empty();
  for (ScoredAction& scored : score_candidates(part, face_size, options, work, 0, taper)) {
    RegionCandidate c;
    c.action = scored.action;
    c.reward = scored.reward;
    c.pieces = static_cast<int>(scored.outcome->pieces.size());
    c.always = scored.action.kind == RegionAction::Kind::Template && finishing_template;
    if (scored.action.kind == RegionAction::Kind::Cut) {
      for (const Region& piece : scored.outcome->pieces) {
        if (is_block(piece, options.rules)) {
          ++c.blocks;
        } else {
          c.to_cut.push_back(piece);
        }
      }
      const auto found = vertex_at.find({scored.action.cut.origin.x, scored.action.cut.origin.y});
      if (found != vertex_at.end()) {
        c.vertex = found->second;
        at_vertex[static_cast<size_t>(c.vertex)].push_back(result.candidates.size());
      }
    }
    result.candidates.push_back(std::move(c));
  }
  for (size_t v = 0; v < reflex.size(); ++v) {
    std::array<float, kVertexLookahead> f{};
    f[0] = reflex[v] ? 1.0f : 0.0f;
    // The two best by reward, the earlier first among equals.
    int best[2] = {-1, -1};
    for (const size_t k : at_vertex[v]) {
      const double r = result.candidates[k].reward;
      if (best[0] < 0 || r > result.candidates[static_cast<size_t>(best[0])].reward) {
        best[1] = best[0];
        best[0] = static_cast<int>(k);
      } else if (best[1] < 0 || r > result.candidates[static_cast<size_t>(best[1])].reward) {
        best[1] = static_cast<int>(k);
      }
    }
    for (int j = 0; j < 2; ++j) {
      const size_t s = static_cast<size_t>(j);
      if (best[j] < 0) {
        f[1 + s] = static_cast<float>(nothing / scale);
        f[3 + s] = 0.25f;
        f[5 + s] = 0.0f;
        continue;
      }
      const RegionCandidate& c = result.candidates[static_cast<size_t>(best[j])];
      f[1 + s] = static_cast<float>(c.reward / scale);
      f[3 + s] = static_cast<float>(c.pieces) / 4.0f;
      f[5 + s] = static_cast<float>(c.blocks) / static_cast<float>(c.pieces);
    }
    result.vertex_features.push_back(f);
  }
  result.scale = {static_cast<float>(part.bbox().longer_side() / face_size),
                  static_cast<float>(std::sqrt(part.area()) / face_size)};
  return result;
}

std::vector<size_t> best_candidates(const std::vector<RegionCandidate>& candidates, size_t keep) {
  std::vector<size_t> order(candidates.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  if (keep == 0 || keep >= order.size()) return order;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return candidates[a].reward > candidates[b].reward; });
  std::vector<size_t> kept(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep));
  for (size_t k = keep; k < order.size(); ++k) {
    if (candidates[order[k]].always) kept.push_back(order[k]);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

std::optional<RegionCandidate> region_candidate(const Region& part, const RegionAction& action, double face_size,
                                                const RegionEpisodeOptions& options, bool taper) {
  if (action.kind != RegionAction::Kind::Cut) return std::nullopt;
  CutOutcome outcome;
  try {
    outcome = cut_region(part, action.cut);
  } catch (const std::exception&) {
    return std::nullopt;  // a cut the engine refuses (grazing a vertex, outside the part) is no candidate
  }
  if (outcome.pieces.size() < 2 || !makes_progress(part, outcome.pieces, options.rules)) return std::nullopt;
  RegionCandidate c;
  c.action = action;
  c.reward = region_cut_reward(options.reward, outcome, face_size, options.rules);
  if (taper) c.reward -= pieces_taper_cost(outcome.pieces, options.rules);
  c.pieces = static_cast<int>(outcome.pieces.size());
  for (Region& piece : outcome.pieces) {
    if (is_block(piece, options.rules)) {
      ++c.blocks;
    } else {
      c.to_cut.push_back(std::move(piece));
    }
  }
  int index = 0;
  for (const Ring& loop : part.loops()) {
    for (const Point2& p : loop) {
      if (p.x == action.cut.origin.x && p.y == action.cut.origin.y && c.vertex < 0) c.vertex = index;
      ++index;
    }
  }
  return c;
}

std::vector<size_t> best_at_vertices(const std::vector<RegionCandidate>& candidates, size_t count) {
  std::vector<size_t> order(candidates.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return candidates[a].reward > candidates[b].reward; });
  std::vector<size_t> best;
  for (const size_t k : order) {
    if (best.size() >= count) break;
    const int v = candidates[k].vertex;
    if (v >= 0 && std::none_of(best.begin(), best.end(), [&](size_t b) { return candidates[b].vertex == v; })) {
      best.push_back(k);
    }
  }
  return best;
}

}  // namespace autoblock
