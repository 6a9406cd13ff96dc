// One step of lookahead from a part: every distinct cut through its corners, with the reward it
// earns and the pieces left to cut, and per-vertex summaries of the two cuts at each corner.
//
// The environment is known and exact (the grid engine cuts in microseconds), so an agent can look
// one cut ahead instead of guessing what a cut does; the lookahead agent (lookahead_agent.h) plans
// with it and its value network reads the per-vertex summaries as node features.
#pragma once

#include <array>
#include <vector>

#include "core/env/reward.h"
#include "core/geometry/axis_cut.h"
#include "core/geometry/part.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {

struct LineCandidate {
  AxisLine line;
  int vertex = 0;                  // the first model vertex on the line (part_boundary order, flattened)
  double reward = 0.0;             // under the preset
  int pieces = 0;                  // N
  int rectangles = 0;              // N_q
  std::vector<Part> to_cut;        // the pieces that are not rectangles
};

// Per vertex: reflex (0/1), then for the horizontal and the vertical cut there: reward / scale,
// N / 4, N_q / N (a cut along the boundary only: its reward, N = 1, N_q = 0).
constexpr int kVertexLookahead = 7;
// Per node: the part's bounding-box longer side and the square root of its area, over the face size.
constexpr int kPartScale = 2;

struct PartLookahead {
  std::vector<LineCandidate> lines;  // distinct lines through corners that split the part
  std::vector<std::array<float, kVertexLookahead>> vertex_features;
  std::array<float, kPartScale> scale{};
};

// The scale dividing rewards in the features: 10 for Eq. (1) (rewards up to about 12), 1 for the
// mesh preset.
double lookahead_reward_scale(RewardPreset preset);

// Inputs:  part; loops, part_boundary(part); face_size (GridFace::size); preset.
// Outputs: its lookahead (see above).
PartLookahead look_ahead(const Part& part, const std::vector<CornerRing>& loops, double face_size, RewardPreset preset);

}  // namespace autoblock
