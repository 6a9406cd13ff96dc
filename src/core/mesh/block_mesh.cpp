#include "core/mesh/block_mesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/mesh/transfinite.h"

namespace autoblock {

namespace {

// Which model edges lie on an arc of the face (-1: none): those merge_arc_chains marked, else the
// boundary edges (used by one block's side) that are chords of an arc.
std::vector<int> edge_arcs(const BlockModel& model, const FaceArcs& arcs) {
  std::vector<int> uses(model.edges.size(), 0);
  for (const ModelBlock& block : model.blocks) {
    for (const ModelSide& side : block.sides) {
      for (const int e : side.edges) ++uses[static_cast<size_t>(e)];
    }
  }
  std::vector<int> on(model.edges.size(), -1);
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& edge = model.edges[e];
    if (edge.arc >= 0) {
      on[e] = edge.arc;
      continue;
    }
    if (uses[e] != 1) continue;
    on[e] = arcs.arc_of_chord(model.vertices[static_cast<size_t>(edge.a)], model.vertices[static_cast<size_t>(edge.b)]);
  }
  return on;
}

}  // namespace

std::vector<double> graded_fractions(int n, double total, double first_a, double first_b, double ratio) {
  std::vector<double> out(static_cast<size_t>(n) + 1, 0.0);
  const double uniform = total / n;
  const bool grade_a = first_a > 0.0 && first_a < uniform, grade_b = first_b > 0.0 && first_b < uniform;
  if (n < 2 || !(total > 0.0) || (!grade_a && !grade_b)) {
    for (int k = 0; k <= n; ++k) out[static_cast<size_t>(k)] = static_cast<double>(k) / n;
    return out;
  }
  // Interval k's size, uncapped: the smaller of the two progressions (scaled by lambda).
  auto grown = [&](int k, double lambda) {
    double w = 1e300;
    if (grade_a) w = std::min(w, lambda * first_a * std::pow(ratio, k));
    if (grade_b) w = std::min(w, lambda * first_b * std::pow(ratio, n - 1 - k));
    return w;
  };
  auto sum = [&](double lambda, double cap) {
    double s = 0.0;
    for (int k = 0; k < n; ++k) s += std::min(cap, grown(k, lambda));
    return s;
  };
  double lambda = 1.0, cap = 1e300;
  const double most = sum(1.0, 1e300);
  if (most < total) {
    lambda = total / most;  // the progressions cannot fill the edge: longer first intervals
  } else {
    double lo = uniform, hi = total;  // the cap: sum(cap) <= total at the uniform size, >= at the total
    for (int round = 0; round < 100; ++round) {
      const double mid = 0.5 * (lo + hi);
      (sum(1.0, mid) < total ? lo : hi) = mid;
    }
    cap = 0.5 * (lo + hi);
  }
  double s = 0.0;
  for (int k = 0; k < n; ++k) {
    s += std::min(cap, grown(k, lambda));
    out[static_cast<size_t>(k) + 1] = s;
  }
  for (double& f : out) f /= s;
  out.back() = 1.0;
  return out;
}

QuadMesh block_model_mesh(const BlockModel& model, const std::vector<int>& intervals, double z, const FaceArcs* arcs,
                          const std::vector<char>* by_length, const ArcEndGrading* grading) {
  if (intervals.size() != model.edges.size()) throw std::logic_error("block_model_mesh: one count per edge expected");
  QuadMesh mesh;
  mesh.z = z;
  mesh.blocks = model.parts;
  mesh.nodes = model.vertices;  // node v is model vertex v
  const std::vector<int> on_arc = arcs && !arcs->empty() ? edge_arcs(model, *arcs) : std::vector<int>(model.edges.size(), -1);
  for (size_t e = 0; e < model.edges.size(); ++e) {
    if (on_arc[e] < 0) continue;
    const CircularArc& arc = arcs->arcs[static_cast<size_t>(on_arc[e])];
    for (const int v : {model.edges[e].a, model.edges[e].b}) {
      mesh.nodes[static_cast<size_t>(v)] = project_to_circle(model.vertices[static_cast<size_t>(v)], arc);
    }
  }

  // Every edge's nodes from a to b, its vertices included.
  std::vector<std::vector<int>> edge_nodes(model.edges.size());
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& edge = model.edges[e];
    const int n = intervals[e];
    if (n < 1) throw std::logic_error("block_model_mesh: an edge without intervals");
    const Point2 a = mesh.nodes[static_cast<size_t>(edge.a)], b = mesh.nodes[static_cast<size_t>(edge.b)];
    std::vector<int>& nodes = edge_nodes[e];
    nodes.push_back(edge.a);
    if (on_arc[e] >= 0) {
      // On the arc, evenly in angle: over the turn merge_arc_chains measured along the chain, or (a
      // single chord spans less than a half turn) the shorter way.
      const CircularArc& arc = arcs->arcs[static_cast<size_t>(on_arc[e])];
      const double ta = std::atan2(a.y - arc.center.y, a.x - arc.center.x);
      double turn = std::atan2(b.y - arc.center.y, b.x - arc.center.x) - ta;
      if (turn > M_PI) turn -= 2.0 * M_PI;
      if (turn < -M_PI) turn += 2.0 * M_PI;
      if (edge.arc >= 0) turn = edge.arc_sweep;
      // The largest first turn from each end of the edge that is an end of the arc with a limit.
      auto end_step = [&](Point2 p) {
        const int end = grading ? arc.end_at(p, arcs->tolerance) : -1;
        return end < 0 ? 0.0 : grading->steps[static_cast<size_t>(on_arc[e])][static_cast<size_t>(end)];
      };
      const double first_a = end_step(a), first_b = end_step(b);
      // (Ungraded, the spacing is computed as it always was: smoothing follows another path when the
      // nodes move by their last bit.)
      const std::vector<double> at = first_a > 0.0 || first_b > 0.0
                                         ? graded_fractions(n, std::fabs(turn), first_a, first_b, grading->ratio)
                                         : std::vector<double>{};
      for (int k = 1; k < n; ++k) {
        const double t = at.empty() ? ta + turn * static_cast<double>(k) / n : ta + turn * at[static_cast<size_t>(k)];
        nodes.push_back(static_cast<int>(mesh.nodes.size()));
        mesh.nodes.push_back(Point2{arc.center.x + arc.radius * std::cos(t), arc.center.y + arc.radius * std::sin(t)});
      }
      nodes.push_back(edge.b);
      continue;
    }
    for (int k = 1; k < n; ++k) {
      const double t = static_cast<double>(k) / n;
      nodes.push_back(static_cast<int>(mesh.nodes.size()));
      mesh.nodes.push_back(Point2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
    nodes.push_back(edge.b);
  }

  for (size_t b = 0; b < model.blocks.size(); ++b) {
    const ModelBlock& block = model.blocks[b];
    // Side k's nodes from corner k to corner k + 1.
    std::vector<int> side_ids[4];
    for (int k = 0; k < 4; ++k) {
      const ModelSide& side = block.sides[static_cast<size_t>(k)];
      std::vector<int>& ids = side_ids[k];
      for (size_t i = 0; i < side.edges.size(); ++i) {
        const std::vector<int>& nodes = edge_nodes[static_cast<size_t>(side.edges[i])];
        const bool forward = side.forward[i] != 0;
        for (size_t j = ids.empty() ? 0 : 1; j < nodes.size(); ++j) ids.push_back(forward ? nodes[j] : nodes[nodes.size() - 1 - j]);
      }
    }
    if (side_ids[0].size() != side_ids[2].size() || side_ids[1].size() != side_ids[3].size() || side_ids[0].size() < 2 ||
        side_ids[1].size() < 2) {
      throw std::logic_error("block_model_mesh: opposite sides of block " + std::to_string(b + 1) + " have different node counts");
    }
    // Transfinite sides: bottom c0 -> c1 (side 0), right c1 -> c2 (side 1), top c3 -> c2 (side 2
    // reversed), left c0 -> c3 (side 3 reversed).
    std::vector<int> bottom = side_ids[0], right = side_ids[1];
    std::vector<int> top(side_ids[2].rbegin(), side_ids[2].rend()), left(side_ids[3].rbegin(), side_ids[3].rend());
    add_mapped_block(mesh, bottom, top, left, right, block.part, by_length && (*by_length)[b]);
  }
  return mesh;
}

}  // namespace autoblock
