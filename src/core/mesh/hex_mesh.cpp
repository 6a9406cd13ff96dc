#include "core/mesh/hex_mesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/common/error.h"

namespace autoblock {
namespace {

constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

}  // namespace

std::array<Point3, 8> HexMesh::corners(size_t hex) const {
  std::array<Point3, 8> c;
  for (size_t k = 0; k < 8; ++k) c[k] = nodes[static_cast<size_t>(hexes[hex][k])];
  return c;
}

std::array<int, 4> hex_face_nodes(const std::array<int, 8>& hex, int side) {
  const int* f = kHexFaces[side];
  return {hex[static_cast<size_t>(f[0])], hex[static_cast<size_t>(f[1])], hex[static_cast<size_t>(f[2])],
          hex[static_cast<size_t>(f[3])]};
}

std::vector<double> layer_stations(int layers, double grading) {
  if (layers < 1) throw InputError("the number of layers must be at least 1");
  if (!std::isfinite(grading) || !(grading > 0)) throw InputError("the grading must be a positive number");
  std::vector<double> s(static_cast<size_t>(layers) + 1);
  const double total = std::fabs(grading - 1.0) < 1e-12 ? layers : (std::pow(grading, layers) - 1.0) / (grading - 1.0);
  double thickness = 1.0, at = 0.0;
  for (int k = 1; k < layers; ++k) {
    at += thickness;
    thickness *= grading;
    s[static_cast<size_t>(k)] = at / total;
  }
  s.back() = 1.0;
  return s;
}

std::vector<double> layer_stations(int layers, double grading, const std::vector<double>& splits) {
  if (splits.empty()) return layer_stations(layers, grading);
  if (layers < 1) throw InputError("the number of layers must be at least 1");
  std::vector<double> ends{0.0};
  ends.insert(ends.end(), splits.begin(), splits.end());
  ends.push_back(1.0);
  const size_t stretches = ends.size() - 1;
  // Each stretch its share of the layers, at least one; the rest by the largest remainders.
  std::vector<int> count(stretches);
  std::vector<std::pair<double, size_t>> remainders;
  int given = 0;
  for (size_t k = 0; k < stretches; ++k) {
    const double share = layers * (ends[k + 1] - ends[k]);
    count[k] = std::max(1, static_cast<int>(std::floor(share)));
    given += count[k];
    remainders.push_back({share - count[k], k});  // below 0 when raised to one
  }
  std::stable_sort(remainders.begin(), remainders.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (size_t i = 0; given < layers && i < remainders.size(); ++i, ++given) ++count[remainders[i].second];
  std::vector<double> s{0.0};
  for (size_t k = 0; k < stretches; ++k) {
    const std::vector<double> within = layer_stations(count[k], grading);
    for (size_t i = 1; i < within.size(); ++i) s.push_back(i + 1 == within.size() ? ends[k + 1] : ends[k] + within[i] * (ends[k + 1] - ends[k]));
  }
  return s;
}

HexMesh sweep_quad_mesh(const QuadMesh& cap, const SweepFrame& where, const std::vector<double>& stations) {
  if (stations.size() < 2) throw std::logic_error("sweep_quad_mesh: fewer than two stations");
  HexMesh out;
  out.blocks = cap.blocks;
  out.layers = static_cast<int>(stations.size()) - 1;
  const size_t n = cap.nodes.size();
  out.nodes.reserve(n * stations.size());
  for (double s : stations) {
    for (const Point2& p : cap.nodes) {
      Point3 q = where.frame.apply(p.x, p.y, cap.z);
      for (size_t k = 0; k < 3; ++k) q[k] += s * where.sweep[k];
      out.nodes.push_back(q);
    }
  }
  // The quads turn counter-clockwise about the plane's +Z (the rotation's third column): when the
  // sweep goes the other way, they are taken in reverse so that every hexahedron has a positive volume.
  const auto& r = where.frame.rotation;
  const bool reverse = r[2] * where.sweep[0] + r[5] * where.sweep[1] + r[8] * where.sweep[2] < 0;
  std::vector<std::array<int, 4>> bottoms;
  bottoms.reserve(cap.quads.size());
  for (const auto& q : cap.quads) bottoms.push_back(reverse ? std::array<int, 4>{q[0], q[3], q[2], q[1]} : q);

  // The boundary edges of the quad mesh (used by one quad), as (quad, its local edge) -> side face,
  // per stretch between splits.
  const size_t stretches = where.splits.size() + 1;
  std::vector<std::vector<std::array<int, 4>>> edge_face(stretches, std::vector<std::array<int, 4>>(cap.quads.size(), {0, 0, 0, 0}));
  {
    std::vector<MeshEdge> edges = mesh_edges(cap);
    auto boundary = [&](int a, int b) {
      const int lo = std::min(a, b), hi = std::max(a, b);
      auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(lo, hi),
                                 [](const MeshEdge& e, const std::pair<int, int>& k) { return std::make_pair(e.a, e.b) < k; });
      return it != edges.end() && it->a == lo && it->b == hi && it->uses == 1;
    };
    for (size_t q = 0; q < bottoms.size(); ++q) {
      for (size_t k = 0; k < 4; ++k) {
        const int a = bottoms[q][k], b = bottoms[q][(k + 1) % 4];
        if (!boundary(a, b)) continue;
        for (size_t j = 0; j < stretches; ++j) {
          edge_face[j][q][k] = where.side_face(out.nodes[static_cast<size_t>(a)], out.nodes[static_cast<size_t>(b)], static_cast<int>(j));
        }
      }
    }
  }
  const int nn = static_cast<int>(n);
  for (int layer = 0; layer < out.layers; ++layer) {
    // The stretch the layer lies in: the splits below its middle.
    const double middle = 0.5 * (stations[static_cast<size_t>(layer)] + stations[static_cast<size_t>(layer) + 1]);
    const auto& faces = edge_face[static_cast<size_t>(std::upper_bound(where.splits.begin(), where.splits.end(), middle) - where.splits.begin())];
    for (size_t q = 0; q < bottoms.size(); ++q) {
      const auto& b = bottoms[q];
      const int lo = layer * nn, hi = (layer + 1) * nn;
      const int hex = static_cast<int>(out.hexes.size());
      out.hexes.push_back({lo + b[0], lo + b[1], lo + b[2], lo + b[3], hi + b[0], hi + b[1], hi + b[2], hi + b[3]});
      out.hex_block.push_back(cap.quad_block[q]);
      if (layer == 0) out.boundary.push_back({hex, 0, where.bottom_face});
      if (layer + 1 == out.layers) out.boundary.push_back({hex, 1, where.top_face});
      for (int k = 0; k < 4; ++k) {
        if (faces[q][static_cast<size_t>(k)] != 0) out.boundary.push_back({hex, 2 + k, faces[q][static_cast<size_t>(k)]});
      }
    }
  }
  return out;
}

}  // namespace autoblock
