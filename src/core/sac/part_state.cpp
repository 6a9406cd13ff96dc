#include "core/sac/part_state.h"

#include <array>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "core/geometry/part_boundary.h"
#include "core/sac/deploy_profile.h"

namespace autoblock {

std::shared_ptr<const PartState> make_part_state(const Part& part, const PartStateOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto state = std::make_shared<PartState>();
  state->graph = part_graph(part, options.graph);
  const auto graph_done = Clock::now();
  DeployProfile& profile = deploy_profile();
  profile.graph_seconds += std::chrono::duration<double>(graph_done - start).count();
  ++profile.states;
  if (profile.graph_nodes.size() < (1u << 22)) profile.graph_nodes.push_back(state->graph.node_count());
  struct LookaheadClock {  // adds the rest of this function to the lookahead time, however it returns
    Clock::time_point since;
    ~LookaheadClock() { deploy_profile().lookahead_seconds += std::chrono::duration<double>(Clock::now() - since).count(); }
  } lookahead_clock{graph_done};
  const std::vector<CornerRing> loops = part_boundary(part);
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    for (int k = 0; k < static_cast<int>(loops[static_cast<size_t>(l)].size()); ++k) {
      state->observations.push_back(observe_vertex(part, loops, l, k));
    }
  }
  if (state->observations.size() != state->graph.vertex_nodes.size()) {
    throw std::logic_error("make_part_state: graph and observations disagree on the vertices");
  }
  if (!options.lookahead) return state;
  PartLookahead lookahead = look_ahead(part, loops, options.face_size, options.reward);
  set_lookahead_features(*state, lookahead.vertex_features, lookahead.scale);
  state->lines = std::move(lookahead.lines);
  return state;
}

void set_lookahead_features(PartState& state, const std::vector<std::array<float, kVertexLookahead>>& vertex_features,
                            const std::array<float, kPartScale>& scale) {
  if (vertex_features.size() != state.graph.vertex_nodes.size()) {
    throw std::logic_error("set_lookahead_features: one summary per model vertex expected");
  }
  const size_t nodes = state.graph.positions.size();
  state.feature_count = kLookaheadFeatures;
  state.features.assign(nodes * kLookaheadFeatures, 0.0f);
  for (size_t n = 0; n < nodes; ++n) {
    float* row = &state.features[n * kLookaheadFeatures];
    for (int k = 0; k < 3; ++k) row[k] = state.graph.features[n][static_cast<size_t>(k)];
    for (int k = 0; k < kPartScale; ++k) row[3 + kVertexLookahead + k] = scale[static_cast<size_t>(k)];
  }
  for (size_t v = 0; v < state.graph.vertex_nodes.size(); ++v) {
    float* row = &state.features[static_cast<size_t>(state.graph.vertex_nodes[v]) * kLookaheadFeatures];
    for (int k = 0; k < kVertexLookahead; ++k) row[3 + k] = vertex_features[v][static_cast<size_t>(k)];
  }
}

namespace {

// A displacement or point under the symmetry: mirror x first, then quarter turns (x, y) -> (-y, x).
std::array<double, 2> transformed(double x, double y, int symmetry) {
  if (symmetry & 1) x = -x;
  for (int turn = 0; turn < (symmetry >> 1); ++turn) {
    const double nx = -y;
    y = x;
    x = nx;
  }
  return {x, y};
}

}  // namespace

std::shared_ptr<const PartState> symmetric_view(const PartState& state, int symmetry) {
  if (symmetry < 0 || symmetry > 7) throw std::logic_error("symmetric_view: symmetry must be in 0..7");
  auto view = std::make_shared<PartState>();
  view->graph.features = state.graph.features;
  view->graph.edges = state.graph.edges;
  view->graph.vertex_nodes = state.graph.vertex_nodes;
  view->graph.positions.reserve(state.graph.positions.size());
  for (const Point2& p : state.graph.positions) {
    const auto [x, y] = transformed(p.x, p.y, symmetry);
    view->graph.positions.push_back(Point2{x, y});
  }
  // pseudo = d / (2 m) + 0.5 for the edge's displacement d; m, the largest absolute component over
  // the edges, does not change under the square's symmetries, so the centred pseudo-coordinate
  // transforms as d does.
  view->graph.pseudo.reserve(state.graph.pseudo.size());
  for (const auto& p : state.graph.pseudo) {
    const auto [u, v] = transformed(p[0] - 0.5, p[1] - 0.5, symmetry);
    view->graph.pseudo.push_back({static_cast<float>(u + 0.5), static_cast<float>(v + 0.5)});
  }
  view->feature_count = state.feature_count;
  view->features = state.features;
  const bool swap_axes = ((symmetry >> 1) & 1) != 0;
  if (swap_axes && state.feature_count == kLookaheadFeatures) {
    // Per vertex: reflex, then (reward, N / 4, N_q / N) for direction 0 and 1 interleaved
    // (part_lookahead.h): a quarter turn exchanges the directions.
    for (size_t n = 0; n < view->graph.positions.size(); ++n) {
      float* row = &view->features[n * kLookaheadFeatures + 3];
      for (int k = 1; k < kVertexLookahead; k += 2) std::swap(row[k], row[k + 1]);
    }
  }
  return view;
}

}  // namespace autoblock
