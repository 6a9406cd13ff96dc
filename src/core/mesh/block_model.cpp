#include "core/mesh/block_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace autoblock {
namespace {

// Model vertices found by position within a tolerance: a hash of square cells as wide as the
// tolerance, searched in the 3 x 3 cells around a point.
class VertexIndex {
 public:
  VertexIndex(std::vector<Point2>* vertices, double tolerance) : vertices_(vertices), tolerance_(tolerance) {}

  // The vertex within the tolerance of p, or -1.
  int find(Point2 p) const {
    const auto [cx, cy] = cell(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (int id : it->second) {
          const Point2& v = (*vertices_)[static_cast<size_t>(id)];
          if (std::hypot(v.x - p.x, v.y - p.y) <= tolerance_) return id;
        }
      }
    }
    return -1;
  }

  int find_or_add(Point2 p) {
    if (const int id = find(p); id >= 0) return id;
    const auto [cx, cy] = cell(p);
    const int id = static_cast<int>(vertices_->size());
    vertices_->push_back(p);
    cells_[key(cx, cy)].push_back(id);
    return id;
  }

 private:
  std::pair<std::int64_t, std::int64_t> cell(Point2 p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / tolerance_)), static_cast<std::int64_t>(std::floor(p.y / tolerance_))};
  }
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(y);
  }

  std::vector<Point2>* vertices_;
  double tolerance_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

// How a vertex may move in snap_near_feet: a part's own vertex inside the face, near only; a vertex a
// template makes, near and (with far) far too.
constexpr char kMovesNear = 1, kMovesFar = 2;

struct LoopPiece {
  std::vector<int> loop;  // vertex ids, counter-clockwise
  std::array<int, 4> corners{};  // positions in loop
  int part = 0;
  bool from_template = false;
};

// Vertex ids in order of x, to visit those whose x lies within a side's span (its ends' x, widened by
// the tolerance).
class ByX {
 public:
  explicit ByX(const std::vector<Point2>& vertices) : order_(vertices.size()), xs_(vertices.size()) {
    for (size_t v = 0; v < order_.size(); ++v) order_[v] = static_cast<int>(v);
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return vertices[static_cast<size_t>(a)].x < vertices[static_cast<size_t>(b)].x; });
    for (size_t i = 0; i < order_.size(); ++i) xs_[i] = vertices[static_cast<size_t>(order_[i])].x;
  }
  const std::vector<int>& order() const { return order_; }
  // Calls visit(id) for every vertex whose x (as it was at construction) lies in [x0, x1].
  template <typename Visit>
  void within(double x0, double x1, Visit visit) const {
    for (size_t j = static_cast<size_t>(std::lower_bound(xs_.begin(), xs_.end(), x0) - xs_.begin()); j < xs_.size() && xs_[j] <= x1; ++j) {
      visit(order_[j]);
    }
  }

 private:
  std::vector<int> order_;
  std::vector<double> xs_;
};

// Inputs: p; a side from a to b; tolerance. Output: true where p lies within the tolerance of the side
// and along it more than the tolerance from either end.
bool on_side_inside(Point2 p, Point2 a, Point2 b, double tolerance) {
  const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
  if (!(length > 0.0)) return false;
  const double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / length;
  return t > tolerance && t < length - tolerance && std::fabs((p.x - a.x) * dy - (p.y - a.y) * dx) / length <= tolerance;
}

// Inputs:  pieces, their loops as ids into vertices (counter-clockwise; T-junctions not yet in them);
//          tolerance, how far off a side a vertex may lie and be on it.
// Output:  per vertex, 1 where the pieces round it fill the full turn (inside the face), 0 where they
//          leave a gap (on the face's boundary: an outline's or a hole's).
std::vector<char> inside_face(const std::vector<LoopPiece>& pieces, const std::vector<Point2>& vertices, double tolerance) {
  const size_t n = vertices.size();
  std::vector<double> turn(n, 0.0);
  const ByX by_x(vertices);
  for (const LoopPiece& piece : pieces) {
    const size_t m = piece.loop.size();
    if (m < 3) continue;
    for (size_t i = 0; i < m; ++i) {
      // The piece's angle at its loop vertex i (the inside lies to the left of a counter-clockwise loop).
      const Point2 o = vertices[static_cast<size_t>(piece.loop[i])];
      const Point2 next = vertices[static_cast<size_t>(piece.loop[(i + 1) % m])], prev = vertices[static_cast<size_t>(piece.loop[(i + m - 1) % m])];
      const double ax = next.x - o.x, ay = next.y - o.y, bx = prev.x - o.x, by = prev.y - o.y;
      double angle = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
      if (angle < 0.0) angle += 2.0 * M_PI;
      turn[static_cast<size_t>(piece.loop[i])] += angle;
      // A vertex on the inside of the side from i to i + 1 (a T-junction): half a turn.
      by_x.within(std::min(o.x, next.x) - tolerance, std::max(o.x, next.x) + tolerance, [&](int v) {
        if (on_side_inside(vertices[static_cast<size_t>(v)], o, next, tolerance)) turn[static_cast<size_t>(v)] += M_PI;
      });
    }
  }
  std::vector<char> inside(n, 0);
  for (size_t v = 0; v < n; ++v) inside[v] = std::fabs(turn[v] - 2.0 * M_PI) < 1e-3;
  return inside;
}

// Two templates' feet on the side their parts share, a hair apart, would make a model edge a tiny
// fraction of its neighbours: given an interval, it holds the minimum down; round a ring of parts the
// counts cannot balance at all (each template places its feet from its own part alone: a flange's
// twelve sector O-grids put theirs on the radial lines between them up to 0.004 apart, their holes
// polygonised differently, and admitted no counts). A vertex a template makes (on no part's outline
// as its vertex: a foot, an inner point), nearer another part's vertex than kFootSnap times the
// shortest piece side at either, each on the line of a piece side at the other, is taken to be
// that vertex (the nearest such; snapped vertices move on together).
// With far, a vertex a fair way from the other (within kFarFootSnap of the longest piece side at
// either) is taken to be it too, where no vertex of its pieces lies between them or within the
// distance beyond, and every piece with it as a corner keeps its quadrilateral of corners convex,
// its least sine above sin(20 degrees) and kFarFootShape of what it was.
// A part's own vertex inside the face (kMovesNear: a cut's end, not on the face's boundary) is taken
// to be another part's vertex a hair from it in the same way, near only (24-bolt flange: a cut's end
// 0.005 from the corner of the template beside it, on sides of 5, gave the edge between them two
// intervals and a strip of quads 40 000 times longer than wide). The parts at it change by the hair
// the move takes along their shared side: a side at it turns about its other end, and a template's
// vertex on that side moves with it; the move is made only where every vertex on the inside of a
// side stays on it (no other part's vertex on a side that turns: another cut ending on this one).
// Inputs:  pieces, their loops as ids into vertices; movable, per vertex (kMovesNear, kMovesFar or 0:
//          it stays); tolerance, how far off a side's line a point may lie and be on it; far, as above.
// Outputs: pieces with the snapped vertices replaced (a loop's repeats dropped, its corners kept);
//          vertices without those no loop uses any more (ids renumbered); the number snapped.
int snap_near_feet(std::vector<LoopPiece>& pieces, std::vector<Point2>& vertices, const std::vector<char>& movable,
                   double tolerance, bool far) {
  const size_t n = vertices.size();
  std::vector<double> shortest(n, std::numeric_limits<double>::infinity()), longest(n, 0.0);
  std::vector<std::vector<int>> neighbours(n), parts(n);
  // The pieces with a vertex as a corner: (piece, corner number); the far snap's shape check alone
  // reads them.
  std::vector<std::vector<std::pair<size_t, int>>> cornered(far ? n : 0);
  for (size_t p = 0; p < pieces.size(); ++p) {
    const LoopPiece& piece = pieces[p];
    const size_t m = piece.loop.size();
    for (size_t i = 0; i < m; ++i) {
      const int a = piece.loop[i], b = piece.loop[(i + 1) % m];
      const Point2 pa = vertices[static_cast<size_t>(a)], pb = vertices[static_cast<size_t>(b)];
      const double length = std::hypot(pb.x - pa.x, pb.y - pa.y);
      for (const int v : {a, b}) {
        shortest[static_cast<size_t>(v)] = std::min(shortest[static_cast<size_t>(v)], length);
        longest[static_cast<size_t>(v)] = std::max(longest[static_cast<size_t>(v)], length);
      }
      neighbours[static_cast<size_t>(a)].push_back(b);
      neighbours[static_cast<size_t>(b)].push_back(a);
      parts[static_cast<size_t>(a)].push_back(piece.part);
    }
    if (!far) continue;
    for (int k = 0; k < 4; ++k) cornered[static_cast<size_t>(piece.loop[static_cast<size_t>(piece.corners[static_cast<size_t>(k)])])].emplace_back(p, k);
  }
  for (auto& p : parts) {
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
  }
  auto on_side_line = [&](int p, int v) {  // p on the line of a piece side at v
    const Point2 a = vertices[static_cast<size_t>(v)], q = vertices[static_cast<size_t>(p)];
    for (int w : neighbours[static_cast<size_t>(v)]) {
      const Point2 b = vertices[static_cast<size_t>(w)];
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      if (length > 0.0 && std::fabs((q.x - a.x) * (b.y - a.y) - (q.y - a.y) * (b.x - a.x)) / length <= tolerance) return true;
    }
    return false;
  };
  auto disjoint = [](const std::vector<int>& a, const std::vector<int>& b) {
    for (int x : a) {
      if (std::binary_search(b.begin(), b.end(), x)) return false;
    }
    return true;
  };
  const ByX by_x(vertices);
  const std::vector<int>& order = by_x.order();
  std::vector<int> to(n);
  for (size_t v = 0; v < n; ++v) to[v] = static_cast<int>(v);
  auto root = [&](int v) {
    while (to[static_cast<size_t>(v)] != v) v = to[static_cast<size_t>(v)];
    return v;
  };
  auto at = [&](int v) { return vertices[static_cast<size_t>(root(v))]; };
  // The least sine of the quadrilateral of corners of piece p, its corner k at `moved` (the others
  // where they are now); negative where it does not turn counter-clockwise at every corner.
  auto least_sine = [&](size_t p, int k, Point2 moved) {
    const LoopPiece& piece = pieces[p];
    std::array<Point2, 4> q;
    for (int c = 0; c < 4; ++c) q[static_cast<size_t>(c)] = c == k ? moved : at(piece.loop[static_cast<size_t>(piece.corners[static_cast<size_t>(c)])]);
    double least = 1.0;
    for (size_t c = 0; c < 4; ++c) {
      const Point2 o = q[c], a = q[(c + 1) % 4], b = q[(c + 3) % 4];
      const double ax = a.x - o.x, ay = a.y - o.y, bx = b.x - o.x, by = b.y - o.y;
      const double length = std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
      least = std::min(least, length > 0.0 ? (ax * by - ay * bx) / length : -1.0);
    }
    return least;
  };
  // Vertices others have been made one with (to[w] == v for some w): a far move of v would take them
  // along unchecked (a foot made one with a near foot, then moved past its piece's corner, left an
  // edge three pieces used: a 62-hole plate's template, block_model's logic_error).
  std::vector<char> joined(n, 0);
  // v may move to `to_point` d away: v is no vertex others were made one with, no vertex next to it in
  // a loop lies towards it closer than 2 d, and its pieces keep their shapes.
  const double least_shape = std::sin(20.0 * M_PI / 180.0);
  auto far_move_keeps = [&](int v, Point2 to_point, double d) {
    if (joined[static_cast<size_t>(v)]) return false;
    const Point2 from = at(v);
    const double ux = (to_point.x - from.x) / d, uy = (to_point.y - from.y) / d;
    for (int w : neighbours[static_cast<size_t>(v)]) {
      const Point2 pw = at(w);
      const double t = (pw.x - from.x) * ux + (pw.y - from.y) * uy;
      const double off = std::fabs((pw.x - from.x) * uy - (pw.y - from.y) * ux);
      if (off <= tolerance && t > 0.0 && t < 2.0 * d) return false;
    }
    for (const auto& [p, k] : cornered[static_cast<size_t>(v)]) {
      const double before = least_sine(p, k, from), after = least_sine(p, k, to_point);
      if (after < least_shape || after < kFarFootShape * before) return false;
    }
    return true;
  };
  // (A near move of a part's vertex, below.) p on the inside of the side from a to b, or on either end.
  auto on_inside = [&](Point2 p, Point2 a, Point2 b) { return on_side_inside(p, a, b, tolerance); };
  auto on_or_end = [&](Point2 p, Point2 a, Point2 b) {
    return std::hypot(p.x - a.x, p.y - a.y) <= tolerance || std::hypot(p.x - b.x, p.y - b.y) <= tolerance || on_inside(p, a, b);
  };
  // Every vertex still where the pieces need it with these moves (roots to new places): a vertex on the
  // inside of a side at a moved one stays on it, or on an end; a moved one on the inside of a side
  // stays on it, or on an end.
  auto moves_keep = [&](const std::vector<std::pair<int, Point2>>& all) {
    auto moved = [&](int y) -> const Point2* {
      for (const auto& [m, p] : all) {
        if (m == y) return &p;
      }
      return nullptr;
    };
    auto new_at = [&](int y) {
      const Point2* p = moved(root(y));
      return p ? *p : at(y);
    };
    for (size_t id = 0; id < n; ++id) {
      const int m = root(static_cast<int>(id));
      for (int w : neighbours[id]) {
        const int rw = root(w);
        const Point2 a = at(m), b = at(rw);
        const bool turns = moved(m) || moved(rw);
        if (turns) {
          const Point2 a2 = new_at(m), b2 = new_at(rw);
          bool kept = true;
          by_x.within(std::min(a.x, b.x) - tolerance, std::max(a.x, b.x) + tolerance, [&](int id_y) {
            const int y = root(id_y);
            if (kept && y != m && y != rw && on_inside(at(y), a, b) && !on_or_end(new_at(y), a2, b2)) kept = false;
          });
          if (!kept) return false;
        } else {
          for (const auto& [y, p] : all) {
            if (y != m && y != rw && on_inside(at(y), a, b) && !on_or_end(p, a, b)) return false;
          }
        }
      }
    }
    return true;
  };
  // v may move onto r where every vertex stays where the pieces need it (moves_keep): a side at v turns
  // about its other end unless it runs along the move, and a template's vertex on it (a foot of the
  // template beside) moves with it, at its share of the side; a part's vertex there (another cut's end)
  // forbids the move. *moves: those template vertices and where they go (roots), then v's.
  auto keeps_imprints = [&](int v, int r, std::vector<std::pair<int, Point2>>* moves) {
    moves->clear();
    const Point2 a = at(v), moved = at(r);
    bool part_vertex = false;  // another part's vertex on a side that turns
    for (int w : neighbours[static_cast<size_t>(v)]) {
      const Point2 b = at(w);
      const double length2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
      by_x.within(std::min(a.x, b.x) - tolerance, std::max(a.x, b.x) + tolerance, [&](int id_x) {
        const int x = root(id_x);
        if (part_vertex || x == root(v) || x == root(w) || x == r) return;
        const Point2 p = at(x);
        if (!on_inside(p, a, b) || on_inside(p, moved, b)) return;
        if (movable[static_cast<size_t>(x)] != kMovesFar) {
          part_vertex = true;
          return;
        }
        const double share = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / length2;
        moves->emplace_back(x, Point2{moved.x + share * (b.x - moved.x), moved.y + share * (b.y - moved.y)});
      });
      if (part_vertex) return false;
    }
    moves->emplace_back(root(v), moved);
    return moves_keep(*moves);
  };
  std::vector<std::pair<int, Point2>> moves, best_moves;  // a candidate's; the best one's so far
  int snapped = 0;
  for (size_t i = 0; i < n; ++i) {
    const int v = order[i];
    const size_t vi = static_cast<size_t>(v);
    if (!movable[vi] || parts[vi].empty()) continue;
    const bool may_go_far = far && movable[vi] == kMovesFar;
    const Point2 pv = vertices[vi];
    const double reach = may_go_far ? kFarFootSnap * longest[vi] : kFootSnap * shortest[vi];
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (int step : {-1, 1}) {
      for (long j = static_cast<long>(i) + step; j >= 0 && j < static_cast<long>(n); j += step) {
        const int u = order[static_cast<size_t>(j)];
        const Point2 pu = vertices[static_cast<size_t>(u)];
        if (std::fabs(pu.x - pv.x) > reach) break;
        const double d = std::hypot(pu.x - pv.x, pu.y - pv.y);
        if (d >= best_distance) continue;
        const size_t ui = static_cast<size_t>(u);
        const bool near = d <= kFootSnap * std::min(shortest[vi], shortest[ui]);
        if (!near && !(may_go_far && d <= kFarFootSnap * std::min(longest[vi], longest[ui]))) continue;
        const int r = root(u);
        if (r == v || !disjoint(parts[vi], parts[static_cast<size_t>(r)]) || !on_side_line(u, v) || !on_side_line(v, u)) continue;
        if (movable[vi] == kMovesNear && !keeps_imprints(v, r, &moves)) continue;
        if (!near) {
          const Point2 pr = vertices[static_cast<size_t>(r)];
          const double dr = std::hypot(pr.x - pv.x, pr.y - pv.y);
          if (!(dr > 0.0) || !far_move_keeps(v, pr, dr)) continue;
        }
        best = r;
        best_distance = d;
        if (movable[vi] == kMovesNear) best_moves.swap(moves);
      }
    }
    if (best < 0) continue;
    if (movable[vi] == kMovesNear) {
      for (const auto& [x, p] : best_moves) {
        if (x != v) vertices[static_cast<size_t>(x)] = p;
      }
    }
    to[vi] = best;
    joined[static_cast<size_t>(best)] = 1;
    auto& into = parts[static_cast<size_t>(best)];
    into.insert(into.end(), parts[vi].begin(), parts[vi].end());
    std::sort(into.begin(), into.end());
    into.erase(std::unique(into.begin(), into.end()), into.end());
    ++snapped;
  }
  if (snapped == 0) return 0;
  std::vector<int> renumber(n, -1);
  std::vector<Point2> kept;
  for (LoopPiece& piece : pieces) {
    std::vector<int> loop;
    std::vector<int> position(piece.loop.size());
    for (size_t i = 0; i < piece.loop.size(); ++i) {
      const int r = root(piece.loop[i]);
      int& id = renumber[static_cast<size_t>(r)];
      if (id < 0) {
        id = static_cast<int>(kept.size());
        kept.push_back(vertices[static_cast<size_t>(r)]);
      }
      if (loop.empty() || loop.back() != id) loop.push_back(id);
      position[i] = static_cast<int>(loop.size()) - 1;
    }
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    for (int& c : piece.corners) c = std::min(position[static_cast<size_t>(c)], static_cast<int>(loop.size()) - 1);
    piece.loop = std::move(loop);
  }
  vertices = std::move(kept);
  return snapped;
}

}  // namespace

double BlockModel::side_length(const ModelSide& side) const {
  double total = 0.0;
  for (int e : side.edges) total += edges[static_cast<size_t>(e)].length;
  return total;
}

BlockModel block_model(const RegionDecomposition& d, const BlockRules& rules, double quantum, bool two_corner,
                       FeetSnap snap, double tolerance_quanta, const std::vector<Point2>& boundary_vertices) {
  if (!d.complete()) throw std::logic_error("block_model: the decomposition is incomplete");
  if (!(quantum > 0.0)) throw std::logic_error("block_model: the quantum must be positive");
  BlockModel model;
  model.parts = static_cast<int>(d.finished.size());
  // Vertices are one within the tolerance that imprints a vertex into a side: a vertex nearer a side's
  // end than that is not imprinted, so it must be that end (two templates' feet on their shared side
  // 1.6 quanta apart were neither). They are one up to twice that: where two cuts meet at a shallow
  // angle, the parts on either side round their meeting point to lattice points several quanta apart
  // along the cuts (5 quanta at 15 degrees on face 56 of the arc property test), and each of the two
  // points, imprinted into the other parts' sides, made an edge between them that three pieces used.
  const double tolerance = tolerance_quanta * quantum;
  VertexIndex index(&model.vertices, 2.0 * tolerance);

  // The pieces, their loops as vertex ids.
  std::vector<LoopPiece> pieces;
  for (size_t f = 0; f < d.finished.size(); ++f) {
    const FinishedRegion& part = d.finished[f];
    std::vector<QuadPiece> quads;
    if (part.is_template) {
      quads = template_pieces(part.region, rules, two_corner);
    } else {
      quads.push_back(QuadPiece{part.region.outer(), part.corners});
    }
    for (const QuadPiece& q : quads) {
      LoopPiece piece;
      piece.part = static_cast<int>(f);
      piece.from_template = part.is_template;
      std::vector<int> position(q.ring.size());
      for (size_t i = 0; i < q.ring.size(); ++i) {
        const int id = index.find_or_add(q.ring[i]);
        if (!piece.loop.empty() && piece.loop.back() == id) {
          position[i] = static_cast<int>(piece.loop.size()) - 1;
          continue;
        }
        position[i] = static_cast<int>(piece.loop.size());
        piece.loop.push_back(id);
      }
      while (piece.loop.size() > 1 && piece.loop.back() == piece.loop.front()) piece.loop.pop_back();
      for (int k = 0; k < 4; ++k) {
        piece.corners[static_cast<size_t>(k)] =
            std::min(position[static_cast<size_t>(q.corners[static_cast<size_t>(k)])], static_cast<int>(piece.loop.size()) - 1);
      }
      for (int k = 0; k < 4; ++k) {
        if (piece.corners[static_cast<size_t>(k)] == piece.corners[static_cast<size_t>((k + 1) % 4)]) {
          throw std::logic_error("block_model: two corners of part " + std::to_string(f + 1) + " coincide");
        }
      }
      pieces.push_back(std::move(piece));
    }
  }

  // A vertex a template makes may move (snap_near_feet); a part's own vertex inside the face a hair
  // (near), one on the face's boundary never.
  model.feet = snap;
  if (snap != FeetSnap::placed) {
    const std::vector<char> inside = inside_face(pieces, model.vertices, tolerance);
    std::vector<char> movable(model.vertices.size(), kMovesFar);
    auto own = [&](int v) { movable[static_cast<size_t>(v)] = inside[static_cast<size_t>(v)] ? kMovesNear : 0; };
    for (const LoopPiece& piece : pieces) {
      if (piece.from_template) continue;
      for (int v : piece.loop) own(v);
    }
    for (const FinishedRegion& part : d.finished) {
      if (!part.is_template) continue;
      auto fix = [&](const Ring& ring) {
        for (const Point2& p : ring) {
          if (const int v = index.find(p); v >= 0) own(v);
        }
      };
      fix(part.region.outer());
      for (const Ring& hole : part.region.holes()) fix(hole);
    }
    model.snapped_feet = snap_near_feet(pieces, model.vertices, movable, tolerance, snap == FeetSnap::far);
  }

  // The face's vertices the parts left out (after the snap: they never move), one with a vertex as
  // near as any two are.
  for (const Point2& p : boundary_vertices) index.find_or_add(p);

  // Imprint: every vertex on the inside of a loop's segment goes into the loop, in order along it.
  for (LoopPiece& piece : pieces) {
    std::vector<int> loop;
    std::vector<int> new_position(piece.loop.size());
    const size_t n = piece.loop.size();
    for (size_t i = 0; i < n; ++i) {
      new_position[i] = static_cast<int>(loop.size());
      loop.push_back(piece.loop[i]);
      const Point2 a = model.vertices[static_cast<size_t>(piece.loop[i])];
      const Point2 b = model.vertices[static_cast<size_t>(piece.loop[(i + 1) % n])];
      const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
      if (l2 == 0.0) continue;
      const double length = std::sqrt(l2);
      const double xmin = std::min(a.x, b.x) - tolerance, xmax = std::max(a.x, b.x) + tolerance;
      const double ymin = std::min(a.y, b.y) - tolerance, ymax = std::max(a.y, b.y) + tolerance;
      std::vector<std::pair<double, int>> inside;
      for (size_t v = 0; v < model.vertices.size(); ++v) {
        const Point2 p = model.vertices[v];
        if (p.x < xmin || p.x > xmax || p.y < ymin || p.y > ymax) continue;
        const double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2;
        if (t * length <= tolerance || (1.0 - t) * length <= tolerance) continue;
        const double off = std::fabs((p.x - a.x) * dy - (p.y - a.y) * dx) / length;
        if (off <= tolerance) inside.emplace_back(t, static_cast<int>(v));
      }
      std::sort(inside.begin(), inside.end());
      for (const auto& [t, v] : inside) loop.push_back(v);
    }
    for (int& c : piece.corners) c = new_position[static_cast<size_t>(c)];
    piece.loop = std::move(loop);
  }

  // Edges by their vertex pair, and every piece's four sides.
  std::map<std::pair<int, int>, int> edge_of;
  std::vector<int> uses;
  for (const LoopPiece& piece : pieces) {
    ModelBlock block;
    block.part = piece.part;
    block.from_template = piece.from_template;
    const int n = static_cast<int>(piece.loop.size());
    for (int k = 0; k < 4; ++k) {
      ModelSide& side = block.sides[static_cast<size_t>(k)];
      const int from = piece.corners[static_cast<size_t>(k)], to = piece.corners[static_cast<size_t>((k + 1) % 4)];
      for (int i = from; i != to; i = (i + 1) % n) {
        const int a = piece.loop[static_cast<size_t>(i)], b = piece.loop[static_cast<size_t>((i + 1) % n)];
        const std::pair<int, int> pair{std::min(a, b), std::max(a, b)};
        auto [it, added] = edge_of.emplace(pair, static_cast<int>(model.edges.size()));
        if (added) {
          const Point2 pa = model.vertices[static_cast<size_t>(a)], pb = model.vertices[static_cast<size_t>(b)];
          model.edges.push_back(ModelEdge{a, b, std::hypot(pb.x - pa.x, pb.y - pa.y)});
          uses.push_back(0);
        }
        const int e = it->second;
        if (++uses[static_cast<size_t>(e)] > 2) {
          throw std::logic_error("block_model: an edge of part " + std::to_string(piece.part + 1) + " is used by more than two pieces");
        }
        side.edges.push_back(e);
        side.forward.push_back(model.edges[static_cast<size_t>(e)].a == a);
      }
    }
    model.blocks.push_back(std::move(block));
  }
  return model;
}

void merge_arc_chains(BlockModel& model, const FaceArcs& arcs) {
  if (arcs.empty()) return;
  const size_t edge_count = model.edges.size();
  std::vector<int> uses(edge_count, 0), degree(model.vertices.size(), 0), arc_of(edge_count, -1);
  std::vector<char> corner(model.vertices.size(), 0);
  for (const ModelBlock& block : model.blocks) {
    for (const ModelSide& side : block.sides) {
      for (const int e : side.edges) ++uses[static_cast<size_t>(e)];
      const ModelEdge& first = model.edges[static_cast<size_t>(side.edges.front())];
      corner[static_cast<size_t>(side.forward.front() ? first.a : first.b)] = 1;
    }
  }
  // An arc's ends are vertices of the face (FaceArcs::at_arc_end): no chain runs past one, so that
  // each keeps its node.
  for (size_t v = 0; v < model.vertices.size(); ++v) {
    if (arcs.at_arc_end(model.vertices[v])) corner[v] = 1;
  }
  for (size_t e = 0; e < edge_count; ++e) {
    const ModelEdge& edge = model.edges[e];
    ++degree[static_cast<size_t>(edge.a)];
    ++degree[static_cast<size_t>(edge.b)];
    if (uses[e] == 1) {
      arc_of[e] = arcs.arc_of_chord(model.vertices[static_cast<size_t>(edge.a)], model.vertices[static_cast<size_t>(edge.b)]);
    }
  }
  // The signed turn of a chord about its arc's centre (a chord spans less than a half turn).
  auto turn = [&](int from, int to, const CircularArc& arc) {
    const Point2 a = model.vertices[static_cast<size_t>(from)], b = model.vertices[static_cast<size_t>(to)];
    double t = std::atan2(b.y - arc.center.y, b.x - arc.center.x) - std::atan2(a.y - arc.center.y, a.x - arc.center.x);
    if (t > M_PI) t -= 2.0 * M_PI;
    if (t < -M_PI) t += 2.0 * M_PI;
    return t;
  };
  std::vector<ModelEdge> edges;
  std::vector<int> renumbered(edge_count, -1);  // unmerged edges keep one new number
  for (ModelBlock& block : model.blocks) {
    for (ModelSide& side : block.sides) {
      ModelSide merged;
      for (size_t i = 0; i < side.edges.size(); ++i) {
        const int e = side.edges[i];
        const ModelEdge& edge = model.edges[static_cast<size_t>(e)];
        const int from = side.forward[i] ? edge.a : edge.b, to = side.forward[i] ? edge.b : edge.a;
        const int arc = arc_of[static_cast<size_t>(e)];
        // Go on along the side while the next edge lies on the same arc past a vertex nothing else uses.
        size_t j = i;
        int end = to;
        while (arc >= 0 && j + 1 < side.edges.size() && arc_of[static_cast<size_t>(side.edges[j + 1])] == arc &&
               degree[static_cast<size_t>(end)] == 2 && !corner[static_cast<size_t>(end)]) {
          ++j;
          const ModelEdge& next = model.edges[static_cast<size_t>(side.edges[j])];
          end = side.forward[j] ? next.b : next.a;
        }
        if (j == i) {
          int& n = renumbered[static_cast<size_t>(e)];
          if (n < 0) {
            n = static_cast<int>(edges.size());
            edges.push_back(edge);
            if (arc >= 0) {
              edges.back().arc = arc;
              edges.back().arc_sweep = turn(edge.a, edge.b, arcs.arcs[static_cast<size_t>(arc)]);
            }
          }
          merged.edges.push_back(n);
          merged.forward.push_back(side.forward[i]);
          continue;
        }
        // Chords i..j become one edge from `from` to `end` (boundary edges: this side alone uses them).
        ModelEdge chain{from, end, 0.0, arc, 0.0};
        int at = from;
        for (size_t k = i; k <= j; ++k) {
          const ModelEdge& part = model.edges[static_cast<size_t>(side.edges[k])];
          const int next = side.forward[k] ? part.b : part.a;
          chain.length += part.length;
          chain.arc_sweep += turn(at, next, arcs.arcs[static_cast<size_t>(arc)]);
          at = next;
        }
        merged.edges.push_back(static_cast<int>(edges.size()));
        merged.forward.push_back(1);
        edges.push_back(chain);
        i = j;
      }
      side = std::move(merged);
    }
  }
  model.edges = std::move(edges);
}

}  // namespace autoblock
