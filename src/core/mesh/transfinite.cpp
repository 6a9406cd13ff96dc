#include "core/mesh/transfinite.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autoblock {
namespace {

// Normalised arc length at every node of a chain: 0 at the first, 1 at the last.
std::vector<double> arc_parameters(const std::vector<Point2>& chain) {
  std::vector<double> t(chain.size(), 0.0);
  for (size_t k = 1; k < chain.size(); ++k) {
    t[k] = t[k - 1] + std::hypot(chain[k].x - chain[k - 1].x, chain[k].y - chain[k - 1].y);
  }
  const double total = t.back();
  for (double& value : t) value = total > 0 ? value / total : 0.0;
  t.back() = 1.0;
  return t;
}

// The point of a chain at the normalised arc length t (params: arc_parameters of the chain).
Point2 chain_point(const std::vector<Point2>& chain, const std::vector<double>& params, double t) {
  size_t k = 1;
  while (k + 1 < params.size() && params[k] < t) ++k;
  const double e = params[k] - params[k - 1], f = e > 0 ? std::clamp((t - params[k - 1]) / e, 0.0, 1.0) : 0.0;
  return Point2{chain[k - 1].x + f * (chain[k].x - chain[k - 1].x), chain[k - 1].y + f * (chain[k].y - chain[k - 1].y)};
}

}  // namespace

std::vector<Point2> transfinite_grid_by_length(const std::vector<Point2>& bottom, const std::vector<Point2>& top,
                                               const std::vector<Point2>& left, const std::vector<Point2>& right) {
  std::vector<Point2> grid = transfinite_grid(bottom, top, left, right);  // checks, boundary nodes
  const size_t nu = bottom.size() - 1, nv = left.size() - 1;
  const std::vector<double> ub = arc_parameters(bottom), ut = arc_parameters(top);
  const std::vector<double> vl = arc_parameters(left), vr = arc_parameters(right);
  const Point2 p00 = bottom.front(), p10 = bottom.back(), p01 = top.front(), p11 = top.back();
  for (size_t j = 1; j < nv; ++j) {
    for (size_t i = 1; i < nu; ++i) {
      // (u, v) where the grid lines i (from bottom node i to top node i) and j cross.
      double u = 0.5 * (ub[i] + ut[i]), v = 0.5 * (vl[j] + vr[j]);
      for (int round = 0; round < 4; ++round) {
        const double nu_ = (1 - v) * ub[i] + v * ut[i], nv_ = (1 - u) * vl[j] + u * vr[j];
        u = nu_, v = nv_;
      }
      const Point2 b = chain_point(bottom, ub, u), t = chain_point(top, ut, u);
      const Point2 l = chain_point(left, vl, v), r = chain_point(right, vr, v);
      Point2& p = grid[j * (nu + 1) + i];
      p.x = (1 - v) * b.x + v * t.x + (1 - u) * l.x + u * r.x -
            ((1 - u) * (1 - v) * p00.x + u * (1 - v) * p10.x + u * v * p11.x + (1 - u) * v * p01.x);
      p.y = (1 - v) * b.y + v * t.y + (1 - u) * l.y + u * r.y -
            ((1 - u) * (1 - v) * p00.y + u * (1 - v) * p10.y + u * v * p11.y + (1 - u) * v * p01.y);
    }
  }
  return grid;
}

std::vector<Point2> transfinite_grid(const std::vector<Point2>& bottom, const std::vector<Point2>& top,
                                     const std::vector<Point2>& left, const std::vector<Point2>& right) {
  if (bottom.size() < 2 || left.size() < 2 || top.size() != bottom.size() || right.size() != left.size()) {
    throw std::invalid_argument("transfinite_grid: opposite sides need the same number of nodes (>= 2)");
  }
  if (!(bottom.front() == left.front()) || !(bottom.back() == right.front()) || !(top.front() == left.back()) ||
      !(top.back() == right.back())) {
    throw std::invalid_argument("transfinite_grid: the sides do not meet at common corners");
  }
  const size_t nu = bottom.size() - 1, nv = left.size() - 1;
  const std::vector<double> ub = arc_parameters(bottom), ut = arc_parameters(top);
  const std::vector<double> vl = arc_parameters(left), vr = arc_parameters(right);
  const Point2 p00 = bottom.front(), p10 = bottom.back(), p01 = top.front(), p11 = top.back();
  std::vector<Point2> grid((nu + 1) * (nv + 1));
  for (size_t j = 0; j <= nv; ++j) {
    for (size_t i = 0; i <= nu; ++i) {
      Point2& p = grid[j * (nu + 1) + i];
      if (j == 0) { p = bottom[i]; continue; }
      if (j == nv) { p = top[i]; continue; }
      if (i == 0) { p = left[j]; continue; }
      if (i == nu) { p = right[j]; continue; }
      const double u = 0.5 * (ub[i] + ut[i]), v = 0.5 * (vl[j] + vr[j]);
      const Point2 b = bottom[i], t = top[i], l = left[j], r = right[j];
      // x: interpolate bottom-top, then correct by how far the left and right sides stray from
      // their corners' chord (zero for straight vertical sides).
      p.x = b.x + v * (t.x - b.x) + (1 - u) * (l.x - p00.x - v * (p01.x - p00.x)) +
            u * (r.x - p10.x - v * (p11.x - p10.x));
      // y: interpolate left-right, then correct by the bottom and top sides' departure.
      p.y = l.y + u * (r.y - l.y) + (1 - v) * (b.y - p00.y - u * (p10.y - p00.y)) +
            v * (t.y - p01.y - u * (p11.y - p01.y));
    }
  }
  return grid;
}

void add_mapped_block(QuadMesh& mesh, const std::vector<int>& bottom, const std::vector<int>& top,
                      const std::vector<int>& left, const std::vector<int>& right, int block, bool by_length) {
  auto points = [&](const std::vector<int>& ids) {
    std::vector<Point2> p;
    p.reserve(ids.size());
    for (int id : ids) p.push_back(mesh.nodes[static_cast<size_t>(id)]);
    return p;
  };
  const std::vector<Point2> grid = by_length ? transfinite_grid_by_length(points(bottom), points(top), points(left), points(right))
                                             : transfinite_grid(points(bottom), points(top), points(left), points(right));
  const size_t nu = bottom.size() - 1, nv = left.size() - 1;
  std::vector<int> ids(grid.size());
  for (size_t j = 0; j <= nv; ++j) {
    for (size_t i = 0; i <= nu; ++i) {
      int& id = ids[j * (nu + 1) + i];
      if (j == 0) id = bottom[i];
      else if (j == nv) id = top[i];
      else if (i == 0) id = left[j];
      else if (i == nu) id = right[j];
      else {
        id = static_cast<int>(mesh.nodes.size());
        mesh.nodes.push_back(grid[j * (nu + 1) + i]);
      }
    }
  }
  for (size_t j = 0; j < nv; ++j) {
    for (size_t i = 0; i < nu; ++i) {
      const size_t k = j * (nu + 1) + i;
      mesh.quads.push_back({ids[k], ids[k + 1], ids[k + nu + 2], ids[k + nu + 1]});
      mesh.quad_block.push_back(block);
    }
  }
}

}  // namespace autoblock
