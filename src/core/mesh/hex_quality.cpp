#include "core/mesh/hex_quality.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/mesh/node_buckets.h"

namespace autoblock {
namespace {

// The three neighbours of each corner, right-handed (det > 0 for a box).
constexpr int kNeighbours[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

Point3 minus(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point3 plus(const Point3& a, const Point3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Point3& a) { return std::sqrt(dot(a, a)); }

// det(a, b, c) / (|a| |b| |c|); 0 when a vector has no length.
double scaled_det(const Point3& a, const Point3& b, const Point3& c) {
  const double n = norm(a) * norm(b) * norm(c);
  if (!(n > 0)) return 0.0;
  return dot(cross(a, b), c) / n;
}

// The principal axes (Verdict): sums of the four edges along each direction.
std::array<Point3, 3> principal_axes(const std::array<Point3, 8>& p) {
  auto sum4 = [&](int a0, int a1, int b0, int b1, int c0, int c1, int d0, int d1) {
    return plus(plus(minus(p[a1], p[a0]), minus(p[b1], p[b0])), plus(minus(p[c1], p[c0]), minus(p[d1], p[d0])));
  };
  return {sum4(0, 1, 3, 2, 4, 5, 7, 6), sum4(0, 3, 1, 2, 4, 7, 5, 6), sum4(0, 4, 1, 5, 2, 6, 3, 7)};
}

// The hexahedron's interior angle (radians) along its edge from corner a to its neighbour b.
double dihedral(const std::array<Point3, 8>& p, int a, int b) {
  const int* n = kNeighbours[a];
  int others[2], k = 0;
  for (int i = 0; i < 3; ++i) {
    if (n[i] != b) others[k++] = n[i];
  }
  const Point3 axis = minus(p[static_cast<size_t>(b)], p[static_cast<size_t>(a)]);
  const double l2 = dot(axis, axis);
  if (!(l2 > 0)) return 0.0;
  auto project = [&](int c) {
    const Point3 v = minus(p[static_cast<size_t>(c)], p[static_cast<size_t>(a)]);
    const double t = dot(v, axis) / l2;
    return Point3{v[0] - t * axis[0], v[1] - t * axis[1], v[2] - t * axis[2]};
  };
  const Point3 u = project(others[0]), v = project(others[1]);
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

}  // namespace

HexQuality hex_quality(const std::array<Point3, 8>& p) {
  HexQuality q;
  double jacobian = std::numeric_limits<double>::infinity();
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int* n = kNeighbours[c];
    const Point3 e1 = minus(p[static_cast<size_t>(n[0])], p[static_cast<size_t>(c)]);
    const Point3 e2 = minus(p[static_cast<size_t>(n[1])], p[static_cast<size_t>(c)]);
    const Point3 e3 = minus(p[static_cast<size_t>(n[2])], p[static_cast<size_t>(c)]);
    jacobian = std::min(jacobian, scaled_det(e1, e2, e3));
    for (const Point3& e : {e1, e2, e3}) {
      shortest = std::min(shortest, norm(e));
      longest = std::max(longest, norm(e));
    }
  }
  const std::array<Point3, 3> axes = principal_axes(p);
  jacobian = std::min(jacobian, scaled_det(axes[0], axes[1], axes[2]));
  q.scaled_jacobian = jacobian;
  q.aspect_ratio = shortest > 0 ? longest / shortest : std::numeric_limits<double>::infinity();
  const double n0 = norm(axes[0]), n1 = norm(axes[1]), n2 = norm(axes[2]);
  if (n0 > 0 && n1 > 0 && n2 > 0) {
    q.skew = std::max({std::fabs(dot(axes[0], axes[1])) / (n0 * n1), std::fabs(dot(axes[0], axes[2])) / (n0 * n2),
                       std::fabs(dot(axes[1], axes[2])) / (n1 * n2)});
  } else {
    q.skew = 1.0;
  }
  return q;
}

namespace {

// An edge's key: its two node numbers, the lower first.
std::uint64_t edge_key(int a, int b) {
  const auto na = static_cast<std::uint64_t>(static_cast<std::uint32_t>(a));
  const auto nb = static_cast<std::uint64_t>(static_cast<std::uint32_t>(b));
  return std::min(na, nb) << 32 | std::max(na, nb);
}

}  // namespace

HexMeshQuality hex_mesh_quality(const HexMesh& mesh) {
  if (mesh.hexes.empty()) throw std::logic_error("hex_mesh_quality: no hexahedron");
  HexMeshQuality out;
  out.min_scaled_jacobian = std::numeric_limits<double>::infinity();
  // Every hexahedron's 12 edges as (low node, high node, angle there).
  struct EdgeUse {
    std::uint64_t key;
    double angle;
  };
  // Grouped by their lower node (node_buckets.h): counted first, then written in place.
  NodeBuckets buckets(mesh.nodes.size());
  for (const auto& hex : mesh.hexes) {
    for (int a = 0; a < 8; ++a) {
      for (int b : kNeighbours[a]) {
        if (b > a) buckets.count(static_cast<size_t>(std::min(hex[static_cast<size_t>(a)], hex[static_cast<size_t>(b)])));
      }
    }
  }
  std::vector<EdgeUse> uses(buckets.close());
  for (size_t h = 0; h < mesh.hexes.size(); ++h) {
    const std::array<Point3, 8> p = mesh.corners(h);
    const HexQuality q = hex_quality(p);
    out.min_scaled_jacobian = std::min(out.min_scaled_jacobian, q.scaled_jacobian);
    out.mean_scaled_jacobian += q.scaled_jacobian;
    out.max_aspect_ratio = std::max(out.max_aspect_ratio, q.aspect_ratio);
    out.mean_aspect_ratio += q.aspect_ratio;
    out.max_skew = std::max(out.max_skew, q.skew);
    for (int a = 0; a < 8; ++a) {
      for (int b : kNeighbours[a]) {
        if (b < a) continue;  // each of the 12 edges once
        const int na = mesh.hexes[h][static_cast<size_t>(a)], nb = mesh.hexes[h][static_cast<size_t>(b)];
        uses[buckets.place(static_cast<size_t>(std::min(na, nb)))] = {edge_key(na, nb), dihedral(p, a, b)};
      }
    }
  }
  out.mean_scaled_jacobian /= static_cast<double>(mesh.hexes.size());
  out.mean_aspect_ratio /= static_cast<double>(mesh.hexes.size());
  buckets.sort(uses, [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });
  // The solid's faces that the boundary quads at each boundary edge lie on.
  std::vector<std::pair<std::uint64_t, int>> edge_faces;
  edge_faces.reserve(mesh.boundary.size() * 4);
  for (const BoundaryQuad& b : mesh.boundary) {
    const std::array<int, 4> n = hex_face_nodes(mesh.hexes[static_cast<size_t>(b.hex)], b.side);
    for (size_t i = 0; i < 4; ++i) edge_faces.emplace_back(edge_key(n[i], n[(i + 1) % 4]), b.face);
  }
  std::sort(edge_faces.begin(), edge_faces.end());
  // True when the boundary quads at the edge all lie on one face of the solid (a cylinder's chords too).
  auto inside_one_face = [&](std::uint64_t key) {
    auto it = std::lower_bound(edge_faces.begin(), edge_faces.end(), std::make_pair(key, std::numeric_limits<int>::min()));
    if (it == edge_faces.end() || it->first != key) return false;
    const int face = it->second;
    for (; it != edge_faces.end() && it->first == key; ++it) {
      if (it->second != face) return false;
    }
    return true;
  };
  constexpr double kFlat = 1e-6;  // radians
  for (size_t k = 0; k < uses.size();) {
    int count = 0;
    double angle = 0.0;
    const std::uint64_t key = uses[k].key;
    for (; k < uses.size() && uses[k].key == key; ++k) {
      ++count;
      angle += uses[k].angle;
    }
    ++out.edges;
    const bool interior = std::fabs(angle - 2 * M_PI) < kFlat;
    const bool flat = !interior && (std::fabs(angle - M_PI) <= kSmoothJoin || inside_one_face(key));
    const int structured = interior ? 4 : flat ? 2 : angle < M_PI ? 1 : 3;
    out.interior_edges += interior;
    if (count != structured) {
      ++out.irregular_edges;
      out.irregular_interior_edges += interior;
    }
  }
  return out;
}

}  // namespace autoblock
