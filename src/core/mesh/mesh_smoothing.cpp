#include "core/mesh/mesh_smoothing.h"

#include <algorithm>
#include <array>
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

SmoothingReport smooth_quad_mesh(QuadMesh& mesh, int max_sweeps) {
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
  for (const MeshEdge& e : mesh_edges(mesh)) {
    if (e.uses == 1) fixed[static_cast<size_t>(e.a)] = fixed[static_cast<size_t>(e.b)] = 1;
  }
  auto local_worst = [&](size_t node) {
    double worst = 1e300;
    for (const auto& [q, k] : around[node]) worst = std::min(worst, quad_scaled_jacobian(mesh.corners(static_cast<size_t>(q))));
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
      for (const Point2& c : candidates) {
        mesh.nodes[v] = c;
        const double w = local_worst(v);
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
  report.min_after = worst_jacobian(mesh);
  return report;
}

}  // namespace autoblock
