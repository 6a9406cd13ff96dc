#include "core/mesh/mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace autoblock {

double quad_scaled_jacobian(const std::array<Point2, 4>& p) {
  // Each edge's length once (every edge is two corners' side): four square roots, not eight.
  std::array<double, 4> ex, ey, length;
  for (size_t k = 0; k < 4; ++k) {
    ex[k] = p[(k + 1) % 4].x - p[k].x;
    ey[k] = p[(k + 1) % 4].y - p[k].y;
    length[k] = std::sqrt(ex[k] * ex[k] + ey[k] * ey[k]);
  }
  double worst = 1e300;
  for (size_t k = 0; k < 4; ++k) {
    // Corner k: its sides are edge k (to the next corner) and edge k - 1 reversed (to the previous).
    const size_t j = (k + 3) % 4;
    const double l1 = length[k], l2 = length[j];
    worst = std::min(worst, l1 > 0 && l2 > 0 ? (ex[j] * ey[k] - ey[j] * ex[k]) / (l1 * l2) : 0.0);
  }
  return worst;
}

double quad_edge_ratio(const std::array<Point2, 4>& p) {
  // Squared lengths, one square root (the smoothing asks this of every quad around every node it
  // tries to move: hypot's care for overflow cost a tenth of a plate's meshing).
  double shortest = 1e300, longest = 0.0;
  for (size_t k = 0; k < 4; ++k) {
    const double dx = p[(k + 1) % 4].x - p[k].x, dy = p[(k + 1) % 4].y - p[k].y;
    const double l2 = dx * dx + dy * dy;
    shortest = std::min(shortest, l2);
    longest = std::max(longest, l2);
  }
  return shortest > 0 ? std::sqrt(longest / shortest) : INFINITY;
}

QuadQuality quad_quality(const std::array<Point2, 4>& p) {
  constexpr double kPi = 3.14159265358979323846;
  QuadQuality q;
  q.scaled_jacobian = quad_scaled_jacobian(p);
  q.min_angle = 1e300;
  q.max_angle = -1e300;
  for (int k = 0; k < 4; ++k) {
    const Point2& c = p[static_cast<size_t>(k)];
    const Point2& next = p[static_cast<size_t>((k + 1) % 4)];
    const Point2& prev = p[static_cast<size_t>((k + 3) % 4)];
    const double e1x = next.x - c.x, e1y = next.y - c.y, e2x = prev.x - c.x, e2y = prev.y - c.y;
    const double cross = e1x * e2y - e1y * e2x;
    double angle = std::atan2(cross, e1x * e2x + e1y * e2y) * 180.0 / kPi;  // signed, in (-180, 180]
    if (angle < 0) angle += 360.0;                                            // reflex corners exceed 180
    q.min_angle = std::min(q.min_angle, angle);
    q.max_angle = std::max(q.max_angle, angle);
  }
  q.aspect_ratio = quad_edge_ratio(p);
  // Principal axes as sums of edge vectors (exactly axis-parallel for a rectangle).
  const double x1x = (p[1].x - p[0].x) + (p[2].x - p[3].x), x1y = (p[1].y - p[0].y) + (p[2].y - p[3].y);
  const double x2x = (p[3].x - p[0].x) + (p[2].x - p[1].x), x2y = (p[3].y - p[0].y) + (p[2].y - p[1].y);
  const double n1 = std::hypot(x1x, x1y), n2 = std::hypot(x2x, x2y);
  q.skew = n1 > 0 && n2 > 0 ? std::fabs(x1x * x2x + x1y * x2y) / (n1 * n2) : 1.0;
  return q;
}

MeshQuality mesh_quality(const QuadMesh& mesh) {
  if (mesh.quads.empty()) throw std::invalid_argument("mesh_quality: no quads");
  MeshQuality m;
  m.min_scaled_jacobian = 1e300;
  m.min_angle = 1e300;
  m.max_angle = -1e300;
  for (size_t k = 0; k < mesh.quads.size(); ++k) {
    const QuadQuality q = quad_quality(mesh.corners(k));
    m.min_scaled_jacobian = std::min(m.min_scaled_jacobian, q.scaled_jacobian);
    m.mean_scaled_jacobian += q.scaled_jacobian;
    m.max_aspect_ratio = std::max(m.max_aspect_ratio, q.aspect_ratio);
    m.mean_aspect_ratio += q.aspect_ratio;
    m.max_skew = std::max(m.max_skew, q.skew);
    m.min_angle = std::min(m.min_angle, q.min_angle);
    m.max_angle = std::max(m.max_angle, q.max_angle);
  }
  m.mean_scaled_jacobian /= static_cast<double>(mesh.quads.size());
  m.mean_aspect_ratio /= static_cast<double>(mesh.quads.size());
  // Valence and boundary: edges used by one quad are boundary edges.
  std::vector<int> valence(mesh.nodes.size(), 0);
  for (const auto& quad : mesh.quads) {
    for (int id : quad) ++valence[static_cast<size_t>(id)];
  }
  std::vector<char> boundary(mesh.nodes.size(), 0);
  for (const MeshEdge& e : mesh_edges(mesh)) {
    if (e.uses == 1) boundary[static_cast<size_t>(e.a)] = boundary[static_cast<size_t>(e.b)] = 1;
  }
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (boundary[n] || valence[n] == 0) continue;
    ++m.interior_nodes;
    m.irregular_interior_nodes += valence[n] != 4;
  }
  return m;
}

double judged_jacobian(const MeshQuality& quality) {
  if (!(quality.min_scaled_jacobian > 0.0)) return quality.min_scaled_jacobian - 2.0;
  if (quality.max_aspect_ratio > kDegenerateEdgeRatio) return quality.min_scaled_jacobian - 1.0;
  return quality.min_scaled_jacobian;
}

}  // namespace autoblock
