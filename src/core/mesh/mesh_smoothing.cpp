#include "core/mesh/mesh_smoothing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/mesh/mesh_quality.h"

namespace autoblock {
namespace {

double worst_jacobian(const QuadMesh& mesh) {
  double worst = 1.0;
  for (size_t q = 0; q < mesh.quads.size(); ++q) worst = std::min(worst, quad_scaled_jacobian(mesh.corners(q)));
  return worst;
}

}  // namespace

SmoothingReport smooth_quad_mesh(QuadMesh& mesh, int max_sweeps, int worst_rounds, const FaceArcs* arcs,
                                 const std::vector<Point2>& pinned) {
  SmoothingReport report;
  report.min_before = report.min_after = mesh.quads.empty() ? 0.0 : worst_jacobian(mesh);
  if (max_sweeps <= 0 || mesh.quads.empty()) return report;
  const size_t n = mesh.nodes.size();
  // Quads around every node, with the node's corner position in each.
  std::vector<std::vector<std::pair<int, int>>> around(n);
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    for (int k = 0; k < 4; ++k) around[static_cast<size_t>(mesh.quads[q][static_cast<size_t>(k)])].emplace_back(static_cast<int>(q), k);
  }
  std::vector<char> fixed(n, 0);
  std::vector<std::array<int, 2>> along(n, {-1, -1});  // a boundary node's two boundary neighbours
  for (const MeshEdge& e : mesh_edges(mesh)) {
    if (e.uses != 1) continue;
    fixed[static_cast<size_t>(e.a)] = fixed[static_cast<size_t>(e.b)] = 1;
    for (const auto& [from, to] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
      auto& ends = along[static_cast<size_t>(from)];
      if (ends[0] < 0) {
        ends[0] = to;
      } else if (ends[1] < 0) {
        ends[1] = to;
      } else {
        ends = {-2, -2};  // more than two: the boundary touches itself here; never slides
      }
    }
  }
  // The boundary nodes that may slide along the boundary (worst-first rounds only): all their quads
  // one block's (not where a block's side meets the boundary: the blocks keep their corners), and in
  // line with their two boundary neighbours (a straight stretch of the face's boundary: slides[v] = 1),
  // or on one of arcs' circles with both of them (slides[v] = 2, circle[v] its arc). Such a node stays
  // on that line or circle, strictly between its neighbours.
  std::vector<char> slides(n, 0);
  std::vector<int> circle(n, -1);
  auto on_circle = [&](Point2 p, const CircularArc& arc) {
    return std::fabs(std::hypot(p.x - arc.center.x, p.y - arc.center.y) - arc.radius) <= 1e-9 * arc.radius;
  };
  // A pinned point's node: at the point, to a hair of the mesh's extent (the block model puts it there).
  double extent = 0.0;
  if (!pinned.empty()) {
    for (const Point2& p : mesh.nodes) extent = std::max(extent, std::fabs(p.x) + std::fabs(p.y));
  }
  auto is_pinned = [&](Point2 p) {
    return std::any_of(pinned.begin(), pinned.end(), [&](Point2 q) { return std::hypot(p.x - q.x, p.y - q.y) <= 1e-12 * extent; });
  };
  for (size_t v = 0; v < n; ++v) {
    const auto [a, b] = along[v];
    if (!fixed[v] || a < 0 || b < 0 || mesh.quad_block.empty()) continue;
    if (is_pinned(mesh.nodes[v])) continue;
    bool one_block = true;
    for (const auto& [q, k] : around[v]) {
      one_block = one_block && mesh.quad_block[static_cast<size_t>(q)] == mesh.quad_block[static_cast<size_t>(around[v][0].first)];
    }
    if (!one_block) continue;
    const Point2 pa = mesh.nodes[static_cast<size_t>(a)], pb = mesh.nodes[static_cast<size_t>(b)], pv = mesh.nodes[v];
    const double abx = pb.x - pa.x, aby = pb.y - pa.y, avx = pv.x - pa.x, avy = pv.y - pa.y;
    const double ab2 = abx * abx + aby * aby, t = (avx * abx + avy * aby) / ab2;
    if (ab2 > 0.0 && std::fabs(abx * avy - aby * avx) <= 1e-9 * ab2 && t > 0.0 && t < 1.0) {
      slides[v] = 1;
      continue;
    }
    // A node at an arc's end (a vertex of the face where two arcs of one circle meet, as CAD systems
    // split a hole's circle into halves) keeps its place: the face's vertices keep their nodes.
    const bool arc_end = arcs && arcs->at_arc_end(pv);
    for (size_t k = 0; arcs && k < arcs->arcs.size() && !slides[v] && !arc_end; ++k) {
      const CircularArc& arc = arcs->arcs[k];
      if (!(arc.radius > 0.0) || !on_circle(pv, arc) || !on_circle(pa, arc) || !on_circle(pb, arc)) continue;
      slides[v] = 2;
      circle[v] = static_cast<int>(k);
    }
  }
  // The worst quad around node; with a bar, it stops at the first quad at or below it (a candidate
  // position is taken only when its worst beats the bar, so the rest would not change that).
  auto local_worst = [&](size_t node, double bar = -1e300) {
    double worst = 1e300;
    for (const auto& [q, k] : around[node]) {
      worst = std::min(worst, quad_scaled_jacobian(mesh.corners(static_cast<size_t>(q))));
      if (worst <= bar) break;
    }
    return worst;
  };
  // The edge ratio each quad around a node may reach from the node's present position: the limit, or
  // the quad's ratio there if higher (set_caps); a candidate position past it is refused (capped_worst).
  std::vector<double> caps;
  auto set_caps = [&](size_t node) {
    caps.clear();
    for (const auto& [q, k] : around[node]) caps.push_back(std::max(kSmoothingEdgeRatio, quad_edge_ratio(mesh.corners(static_cast<size_t>(q)))));
  };
  auto capped_worst = [&](size_t node, double bar) {
    const double worst = local_worst(node, bar);
    if (worst <= bar) return worst;
    for (size_t i = 0; i < around[node].size(); ++i) {
      if (quad_edge_ratio(mesh.corners(static_cast<size_t>(around[node][i].first))) > caps[i]) return -1e300;
    }
    return worst;
  };
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    ++report.sweeps;
    double best_gain = 0.0;
    for (size_t v = 0; v < n; ++v) {
      if (fixed[v] || around[v].empty()) continue;
      const Point2 here = mesh.nodes[v];
      Point2 iso{0, 0}, lap{0, 0};
      std::vector<int> neighbours;
      for (const auto& [q, k] : around[v]) {
        const auto& quad = mesh.quads[static_cast<size_t>(q)];
        const Point2 prev = mesh.nodes[static_cast<size_t>(quad[static_cast<size_t>((k + 3) % 4)])];
        const Point2 next = mesh.nodes[static_cast<size_t>(quad[static_cast<size_t>((k + 1) % 4)])];
        const Point2 opposite = mesh.nodes[static_cast<size_t>(quad[static_cast<size_t>((k + 2) % 4)])];
        iso.x += prev.x + next.x - opposite.x;
        iso.y += prev.y + next.y - opposite.y;
        neighbours.push_back(quad[static_cast<size_t>((k + 3) % 4)]);
        neighbours.push_back(quad[static_cast<size_t>((k + 1) % 4)]);
      }
      const double m = static_cast<double>(around[v].size());
      iso = {iso.x / m, iso.y / m};
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      for (int u : neighbours) {
        lap.x += mesh.nodes[static_cast<size_t>(u)].x;
        lap.y += mesh.nodes[static_cast<size_t>(u)].y;
      }
      lap = {lap.x / static_cast<double>(neighbours.size()), lap.y / static_cast<double>(neighbours.size())};
      const std::array<Point2, 4> candidates{iso, lap, Point2{0.5 * (here.x + iso.x), 0.5 * (here.y + iso.y)},
                                             Point2{0.5 * (here.x + lap.x), 0.5 * (here.y + lap.y)}};
      const double current = local_worst(v);
      double best = current;
      Point2 best_at = here;
      set_caps(v);
      for (const Point2& c : candidates) {
        mesh.nodes[v] = c;
        const double w = capped_worst(v, best);
        if (w > best) {
          best = w;
          best_at = c;
        }
      }
      mesh.nodes[v] = best_at;
      if (best > current) {
        ++report.moves;
        best_gain = std::max(best_gain, best - current);
      }
    }
    if (best_gain <= 1e-6) break;
  }
  // Worst first: the sweeps' four candidate positions cannot reach every improvement, and the
  // mesh's minimum is set by its few worst quads. So, in up to worst_rounds rounds (stopping at the
  // first that moves nothing), the free corners of the quads
  // within 0.05 of the minimum (at most kWorstNodes of them, worst first) are each moved by a
  // pattern search: eight directions, a step of a quarter of the node's mean edge length, halved
  // when no direction improves the node's worst quad, a move taken only when it does.
  constexpr int kWorstNodes = 400, kHalvings = 6;
  std::array<Point2, 8> directions;
  for (size_t d = 0; d < 8; ++d) {
    const double a = static_cast<double>(d) * M_PI / 4.0;
    directions[d] = {std::cos(a), std::sin(a)};
  }
  std::vector<double> sj(mesh.quads.size());
  for (int round = 0; round < worst_rounds; ++round) {
    double minimum = 1e300;
    for (size_t q = 0; q < mesh.quads.size(); ++q) {
      sj[q] = quad_scaled_jacobian(mesh.corners(q));
      minimum = std::min(minimum, sj[q]);
    }
    std::vector<std::pair<double, int>> worst_nodes;
    for (size_t q = 0; q < mesh.quads.size(); ++q) {
      if (sj[q] > minimum + 0.05) continue;
      for (int v : mesh.quads[q]) {
        if (!fixed[static_cast<size_t>(v)] || slides[static_cast<size_t>(v)]) worst_nodes.emplace_back(sj[q], v);
      }
    }
    std::sort(worst_nodes.begin(), worst_nodes.end());
    std::vector<char> seen(n, 0);
    int optimised = 0;
    bool improved = false;
    for (const auto& [value, v] : worst_nodes) {
      const size_t node = static_cast<size_t>(v);
      if (seen[node] || optimised == kWorstNodes) continue;
      seen[node] = 1;
      ++optimised;
      double length = 0.0;
      int edges = 0;
      for (const auto& [q, k] : around[node]) {
        const auto& quad = mesh.quads[static_cast<size_t>(q)];
        const Point2 next = mesh.nodes[static_cast<size_t>(quad[static_cast<size_t>((k + 1) % 4)])];
        length += std::hypot(next.x - mesh.nodes[node].x, next.y - mesh.nodes[node].y);
        ++edges;
      }
      double step = 0.25 * length / std::max(1, edges);
      double current = local_worst(node);
      // A boundary node slides: two directions, along the line or the circle through its boundary
      // neighbours, within [0.05, 0.95] of the way from one to the other.
      const bool sliding = fixed[node] != 0;
      const Point2 line_a = sliding ? mesh.nodes[static_cast<size_t>(along[node][0])] : Point2{};
      const Point2 line_b = sliding ? mesh.nodes[static_cast<size_t>(along[node][1])] : Point2{};
      const double line_x = line_b.x - line_a.x, line_y = line_b.y - line_a.y;
      const double line_length = std::hypot(line_x, line_y);
      const CircularArc* arc = slides[node] == 2 ? &arcs->arcs[static_cast<size_t>(circle[node])] : nullptr;
      // On a circle: the neighbours' angles as seen from the node's (wrapped to (-pi, pi]), of opposite signs.
      auto wrapped = [](double angle) { return std::remainder(angle, 2.0 * M_PI); };
      double angle_a = 0.0, angle_b = 0.0, low = 0.05, high = 0.95;
      if (arc) {
        const Point2 c = arc->center, v = mesh.nodes[node];
        const double at = std::atan2(v.y - c.y, v.x - c.x);
        angle_a = wrapped(std::atan2(line_a.y - c.y, line_a.x - c.x) - at);
        angle_b = wrapped(std::atan2(line_b.y - c.y, line_b.x - c.x) - at);
        if (!(angle_a * angle_b < 0.0)) continue;  // not between them on the circle: stays
        // Neither edge turns by more than one of the arc's chord steps (what the conformity check
        // takes for a chord of the arc, FaceArcs::arc_of_chord).
        const double span = std::fabs(angle_b - angle_a), limit = 0.999 * std::fabs(arc->sweep) / arc_chord_count(*arc);
        low = std::max(low, 1.0 - limit / span);
        high = std::min(high, limit / span);
        if (!(low < high)) continue;
        angle_a += at;
        angle_b += at;
      }
      // The path it slides on, from one boundary neighbour (t = 0) to the other (t = 1): a point's
      // parameter, the point at a parameter, and the path's length.
      const double sweep = angle_b - angle_a;
      auto parameter_of = [&](Point2 p) {
        if (arc) return wrapped(std::atan2(p.y - arc->center.y, p.x - arc->center.x) - angle_a) / sweep;
        return ((p.x - line_a.x) * line_x + (p.y - line_a.y) * line_y) / (line_length * line_length);
      };
      auto point_at = [&](double t) {
        if (!arc) return Point2{line_a.x + t * line_x, line_a.y + t * line_y};
        const double angle = angle_a + t * sweep;
        return Point2{arc->center.x + arc->radius * std::cos(angle), arc->center.y + arc->radius * std::sin(angle)};
      };
      const double path_length = arc ? arc->radius * std::fabs(sweep) : line_length;
      set_caps(node);  // again only where the node moves: nothing else here does
      for (int halving = 0; halving < kHalvings && step > 0.0;) {
        const Point2 here = mesh.nodes[node];
        const double at = sliding ? parameter_of(here) : 0.0;
        Point2 best_at = here;
        double best = current;
        for (int d = 0; d < (sliding ? 2 : 8); ++d) {
          if (sliding) {
            mesh.nodes[node] = point_at(std::clamp(at + (d == 0 ? step : -step) / path_length, low, high));
          } else {
            mesh.nodes[node] = {here.x + step * directions[static_cast<size_t>(d)].x, here.y + step * directions[static_cast<size_t>(d)].y};
          }
          const double w = capped_worst(node, best);
          if (w > best) {
            best = w;
            best_at = mesh.nodes[node];
          }
        }
        mesh.nodes[node] = best_at;
        if (!(best_at == here)) set_caps(node);
        if (best > current + 1e-9) {
          current = best;
          improved = true;
          ++report.moves;
        } else {
          step *= 0.5;
          ++halving;
        }
      }
    }
    if (!improved) break;
  }
  report.min_after = worst_jacobian(mesh);
  return report;
}

int untangle_quad_mesh(QuadMesh& mesh, int rings, int max_sweeps) {
  auto inverted = [&] {
    std::vector<char> at(mesh.nodes.size(), 0);
    int count = 0;
    for (size_t q = 0; q < mesh.quads.size(); ++q) {
      if (quad_scaled_jacobian(mesh.corners(q)) > 0.0) continue;
      ++count;
      for (const int v : mesh.quads[q]) at[static_cast<size_t>(v)] = 1;
    }
    return std::pair{count, at};
  };
  auto [count, near] = inverted();
  if (count == 0 || max_sweeps <= 0) return count;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> grown = near;
    for (const auto& quad : mesh.quads) {
      bool touches = false;
      for (const int v : quad) touches = touches || near[static_cast<size_t>(v)];
      if (!touches) continue;
      for (const int v : quad) grown[static_cast<size_t>(v)] = 1;
    }
    near = std::move(grown);
  }
  // The patch: the quads whose nodes are all near, as a mesh of its own.
  QuadMesh patch;
  patch.z = mesh.z;
  patch.blocks = mesh.blocks;
  std::vector<int> index(mesh.nodes.size(), -1);
  std::vector<size_t> node_of;
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    bool inside = true;
    for (const int v : mesh.quads[q]) inside = inside && near[static_cast<size_t>(v)];
    if (!inside) continue;
    std::array<int, 4> quad{};
    for (size_t k = 0; k < 4; ++k) {
      const size_t v = static_cast<size_t>(mesh.quads[q][k]);
      if (index[v] < 0) {
        index[v] = static_cast<int>(patch.nodes.size());
        patch.nodes.push_back(mesh.nodes[v]);
        node_of.push_back(v);
      }
      quad[k] = index[v];
    }
    patch.quads.push_back(quad);
    if (!mesh.quad_block.empty()) patch.quad_block.push_back(mesh.quad_block[q]);
  }
  // A node inside the patch has all its quads there (else an edge of it would be used once: the
  // patch's boundary, which stays).
  smooth_quad_mesh(patch, max_sweeps, 0, nullptr);
  for (size_t i = 0; i < node_of.size(); ++i) mesh.nodes[node_of[i]] = patch.nodes[i];
  return inverted().first;
}

}  // namespace autoblock
