// Smoothing that keeps boundary nodes and never lowers the minimum scaled Jacobian.
#include "core/mesh/mesh_smoothing.h"

#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "core/mesh/mesh_quality.h"

using namespace autoblock;

namespace {

// An n x n grid of parallelograms (shear s), quads counter-clockwise.
QuadMesh sheared_grid(int n, double s) {
  QuadMesh mesh;
  mesh.blocks = 1;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) mesh.nodes.push_back(Point2{i + s * j, static_cast<double>(j)});
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int k = j * (n + 1) + i;
      mesh.quads.push_back({k, k + 1, k + n + 2, k + n + 1});
      mesh.quad_block.push_back(0);
    }
  }
  return mesh;
}

// Checks that the boundary nodes of an (n + 1) x (n + 1) grid stayed on the boundary: the four corners
// where they were, every other one on its side's line, the sides' nodes in their order along it.
void check_boundary_kept(const QuadMesh& mesh, const QuadMesh& before, int n) {
  auto at = [&](const QuadMesh& m, int i, int j) { return m.nodes[static_cast<size_t>(j * (n + 1) + i)]; };
  for (const auto& [i, j] : {std::pair{0, 0}, std::pair{n, 0}, std::pair{n, n}, std::pair{0, n}}) {
    CHECK(at(mesh, i, j) == at(before, i, j));
  }
  // The sides: bottom, right, top, left, each from its first corner to its last.
  for (int side = 0; side < 4; ++side) {
    auto node = [&](const QuadMesh& m, int k) {
      return side == 0 ? at(m, k, 0) : side == 1 ? at(m, n, k) : side == 2 ? at(m, k, n) : at(m, 0, k);
    };
    const Point2 a = node(before, 0), b = node(before, n);
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    double previous = 0.0;
    for (int k = 1; k < n; ++k) {
      const Point2 p = node(mesh, k);
      INFO("side " << side << ", node " << k);
      CHECK(std::fabs(dx * (p.y - a.y) - dy * (p.x - a.x)) <= 1e-9 * length2);  // on the line
      const double t = (dx * (p.x - a.x) + dy * (p.y - a.y)) / length2;
      CHECK(t > previous);  // in order, between the corners
      previous = t;
    }
    CHECK(previous < 1.0);
  }
}

}  // namespace

TEST_CASE("smoothing leaves an affine grid where it is", "[mesh][smoothing]") {
  QuadMesh mesh = sheared_grid(6, 0.4);
  const QuadMesh before = mesh;
  const SmoothingReport r = smooth_quad_mesh(mesh, 20);
  CHECK(r.moves == 0);
  for (size_t v = 0; v < mesh.nodes.size(); ++v) {
    CHECK(mesh.nodes[v].x == Approx(before.nodes[v].x));
    CHECK(mesh.nodes[v].y == Approx(before.nodes[v].y));
  }
  CHECK(r.min_after == Approx(r.min_before));
}

TEST_CASE("smoothing repairs a distorted grid, keeps its boundary, never lowers the minimum", "[mesh][smoothing]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45);
  for (int trial = 0; trial < 20; ++trial) {
    QuadMesh mesh = sheared_grid(8, 0.1 * trial);
    const int n = 8;
    for (int j = 1; j < n; ++j) {
      for (int i = 1; i < n; ++i) {
        Point2& p = mesh.nodes[static_cast<size_t>(j * (n + 1) + i)];
        p.x += jitter(rng);
        p.y += jitter(rng);
      }
    }
    const QuadMesh before = mesh;
    const double min_before = mesh_quality(mesh).min_scaled_jacobian;
    INFO("trial " << trial);
    REQUIRE(smooth_quad_mesh(mesh, 0).moves == 0);
    const SmoothingReport r = smooth_quad_mesh(mesh, 50);
    CHECK(r.min_before == Approx(min_before));
    CHECK(r.min_after >= min_before);
    CHECK(mesh_quality(mesh).min_scaled_jacobian == Approx(r.min_after));
    if (min_before < 0.5) CHECK(r.min_after > min_before + 0.05);
    // Boundary nodes stay on the boundary (the corners where they were).
    check_boundary_kept(mesh, before, n);
  }
}

TEST_CASE("the worst-first pass raises the minimum that the sweeps leave", "[mesh][smoothing]") {
  // Grids whose boundary nodes bunch towards one corner (as where a short block side carries many
  // intervals) and whose interior is jittered: the sweeps' four candidate positions stop short; the
  // pattern search on the worst quads' corners goes further (boundary nodes sliding along their side),
  // never lowering the minimum and keeping the boundary.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  int better = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 8;
    QuadMesh mesh = sheared_grid(n, 0.05 * trial);
    const double bunch = 1.5 + 0.1 * trial;  // x -> n (x / n)^bunch along the bottom side
    for (int i = 1; i < n; ++i) mesh.nodes[static_cast<size_t>(i)].x = n * std::pow(static_cast<double>(i) / n, bunch);
    for (int j = 1; j < n; ++j) {
      for (int i = 1; i < n; ++i) {
        Point2& p = mesh.nodes[static_cast<size_t>(j * (n + 1) + i)];
        p.x += jitter(rng);
        p.y += jitter(rng);
      }
    }
    QuadMesh sweeps_only = mesh;
    const SmoothingReport a = smooth_quad_mesh(sweeps_only, 50, 0);
    const SmoothingReport b = smooth_quad_mesh(mesh, 50);
    INFO("trial " << trial << ": sweeps " << a.min_after << ", with the worst-first pass " << b.min_after);
    CHECK(b.min_after >= a.min_after);
    CHECK(mesh_quality(mesh).min_scaled_jacobian == Approx(b.min_after));
    better += b.min_after > a.min_after + 0.01 ? 1 : 0;
    check_boundary_kept(mesh, sweeps_only, n);
  }
  CHECK(better >= 15);
}

TEST_CASE("boundary nodes slide along a straight side, not where blocks meet, not on a bend", "[mesh][smoothing]") {
  // Two blocks side by side (x in [0, 4] and [4, 8], y in [0, 4]) whose bottom nodes bunch towards
  // x = 0 and whose interior is sheared: the worst quads are at the bottom left. The bottom nodes of the
  // left block slide to the right; the node where the blocks meet (x = 4) stays, and so does every node
  // of the right block's bottom, which bends (an arc's polygon: not in line with its neighbours).
  const int n = 8;
  QuadMesh mesh = sheared_grid(n, 0.0);
  for (size_t q = 0; q < mesh.quads.size(); ++q) mesh.quad_block[q] = (q % n) < static_cast<size_t>(n / 2) ? 0 : 1;
  mesh.blocks = 2;
  for (int i = 1; i < n / 2; ++i) mesh.nodes[static_cast<size_t>(i)].x = 4.0 * std::pow(i / 4.0, 2.5);
  for (int i = n / 2 + 1; i < n; ++i) mesh.nodes[static_cast<size_t>(i)].y = -0.05 * (i - n / 2) * (n - i);
  for (int j = 1; j < n; ++j) {
    for (int i = 1; i < n; ++i) mesh.nodes[static_cast<size_t>(j * (n + 1) + i)].x += 0.3 * (j % 2);
  }
  const QuadMesh before = mesh;
  const SmoothingReport r = smooth_quad_mesh(mesh, 50);
  CHECK(r.min_after >= r.min_before);
  bool slid = false;
  for (int i = 1; i < n / 2; ++i) {
    const Point2 p = mesh.nodes[static_cast<size_t>(i)];
    CHECK(p.y == 0.0);  // on the bottom side
    slid = slid || p.x != before.nodes[static_cast<size_t>(i)].x;
  }
  CHECK(slid);
  for (int i = n / 2; i <= n; ++i) CHECK(mesh.nodes[static_cast<size_t>(i)] == before.nodes[static_cast<size_t>(i)]);
}

TEST_CASE("boundary nodes on an arc slide along its circle, each edge within a chord step", "[mesh][smoothing][arc]") {
  // A quarter annulus (radii 1 and 2), its outer arc's nodes bunched towards angle 0 and its interior
  // jittered. Given the outer arc (FaceArcs), its nodes slide along the circle; the inner circle's nodes
  // (no arc given) and the arc's ends stay; no edge of the outer arc turns by more than its chord step.
  const int n = 8;
  const double quarter = M_PI / 2.0;
  QuadMesh mesh;
  mesh.blocks = 1;
  auto angle_of = [&](int i, int j) { return quarter * std::pow(static_cast<double>(i) / n, j == n ? 1.3 : 1.0); };
  for (int j = 0; j <= n; ++j) {
    const double r = 1.0 + static_cast<double>(j) / n;
    for (int i = 0; i <= n; ++i) {
      const double a = angle_of(i, j) + (i > 0 && i < n && j > 0 && j < n ? 0.04 * ((i + j) % 3 - 1) : 0.0);
      mesh.nodes.push_back(Point2{r * std::cos(a), r * std::sin(a)});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int k = j * (n + 1) + i;
      mesh.quads.push_back({k, k + n + 1, k + n + 2, k + 1});  // outwards, then round: counter-clockwise
      mesh.quad_block.push_back(0);
    }
  }
  REQUIRE(quad_scaled_jacobian(mesh.corners(0)) > 0.0);
  FaceArcs arcs;
  arcs.arcs.push_back(CircularArc{Point2{0.0, 0.0}, 2.0, 0.0, quarter, false, 0});
  const QuadMesh before = mesh;
  QuadMesh without = mesh;
  const SmoothingReport with_arc = smooth_quad_mesh(mesh, 30, kWorstRounds, &arcs);
  const SmoothingReport no_arc = smooth_quad_mesh(without, 30, kWorstRounds);
  CHECK(with_arc.min_after >= with_arc.min_before);
  CHECK(with_arc.min_after >= no_arc.min_after);
  const double step = quarter / arc_chord_count(arcs.arcs[0]);
  bool slid = false;
  double previous = 0.0;
  for (int i = 0; i <= n; ++i) {
    const size_t outer = static_cast<size_t>(n * (n + 1) + i), inner = static_cast<size_t>(i);
    const Point2 p = mesh.nodes[outer];
    INFO("node " << i);
    CHECK(std::hypot(p.x, p.y) == Approx(2.0).epsilon(1e-12));
    const double a = std::atan2(p.y, p.x);
    if (i > 0) CHECK(a - previous <= step);
    if (i > 0) CHECK(a > previous);
    previous = a;
    slid = slid || !(p == before.nodes[outer]);
    CHECK(mesh.nodes[inner] == before.nodes[inner]);      // the inner circle: no arc given
    CHECK(without.nodes[outer] == before.nodes[outer]);  // no arcs: the outer one stays too
  }
  CHECK(mesh.nodes[static_cast<size_t>(n * (n + 1))] == before.nodes[static_cast<size_t>(n * (n + 1))]);
  CHECK(mesh.nodes[static_cast<size_t>(n * (n + 1) + n)] == before.nodes[static_cast<size_t>(n * (n + 1) + n)]);
  CHECK(slid);
}

TEST_CASE("untangling smooths the quads about inverted ones alone and leaves the rest", "[mesh][smoothing]") {
  const int n = 16;
  QuadMesh mesh = sheared_grid(n, 0.0);
  // Nothing inverted: nothing moves.
  QuadMesh straight = mesh;
  CHECK(untangle_quad_mesh(straight, 3, 100) == 0);
  for (size_t v = 0; v < mesh.nodes.size(); ++v) CHECK(straight.nodes[v] == mesh.nodes[v]);
  // Two nodes pushed across their neighbours (a fold of several quads) near one corner.
  auto at = [&](int i, int j) -> Point2& { return mesh.nodes[static_cast<size_t>(j * (n + 1) + i)]; };
  at(4, 4) = {5.7, 4.4};
  at(5, 5) = {3.6, 5.8};
  int inverted = 0;
  for (size_t q = 0; q < mesh.quads.size(); ++q) inverted += quad_scaled_jacobian(mesh.corners(q)) <= 0.0;
  REQUIRE(inverted >= 2);
  const QuadMesh before = mesh;
  CHECK(untangle_quad_mesh(mesh, 3, 100) == 0);
  for (size_t q = 0; q < mesh.quads.size(); ++q) CHECK(quad_scaled_jacobian(mesh.corners(q)) > 0.0);
  // Nodes more than the rings (and the inverted quads' own) from the fold stay, and so does the
  // boundary; the fold's nodes moved.
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool far = i > 10 || j > 10;
      const bool boundary = i == 0 || j == 0 || i == n || j == n;
      if (far || boundary) {
        INFO("node " << i << ", " << j);
        CHECK(mesh.nodes[static_cast<size_t>(j * (n + 1) + i)] == before.nodes[static_cast<size_t>(j * (n + 1) + i)]);
      }
    }
  }
  CHECK_FALSE(at(4, 4) == before.nodes[static_cast<size_t>(4 * (n + 1) + 4)]);
}

TEST_CASE("smoothing never makes a quad longer than the limit against its shortest edge", "[mesh][smoothing]") {
  // Bilinear grids of quadrilaterals with one short side (a block narrowing to an acute tip): the
  // scaled Jacobian alone is best served by drawing nodes together at the short side, into quads that
  // are triangles with an edge of no length (a generated face's mesh had edges 1e-8 of their quads'
  // size). No quad's longest edge over its shortest may pass kSmoothingEdgeRatio, or its own before
  // smoothing when that was more.
  int degenerate_before = 0;
  for (const double top : {0.02, 0.1, 0.3, 1.0}) {
    for (const int n : {6, 10}) {
      const std::array<Point2, 4> c{Point2{0, 0}, Point2{10, 0}, Point2{5.0 + 0.5 * top, 8}, Point2{5.0 - 0.5 * top, 8}};
      QuadMesh mesh;
      mesh.blocks = 1;
      for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
          const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
          mesh.nodes.push_back(Point2{(1 - u) * (1 - v) * c[0].x + u * (1 - v) * c[1].x + u * v * c[2].x + (1 - u) * v * c[3].x,
                                      (1 - u) * (1 - v) * c[0].y + u * (1 - v) * c[1].y + u * v * c[2].y + (1 - u) * v * c[3].y});
        }
      }
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const int k = j * (n + 1) + i;
          mesh.quads.push_back({k, k + 1, k + n + 2, k + n + 1});
          mesh.quad_block.push_back(0);
        }
      }
      std::vector<double> before(mesh.quads.size());
      for (size_t q = 0; q < mesh.quads.size(); ++q) before[q] = quad_edge_ratio(mesh.corners(q));
      const double min_before = mesh_quality(mesh).min_scaled_jacobian;
      const SmoothingReport r = smooth_quad_mesh(mesh, 30);
      INFO("top " << top << ", " << n << " x " << n << ": min scaled Jacobian " << min_before << " -> " << r.min_after);
      CHECK(r.min_after >= min_before);
      CHECK(r.moves > 0);
      for (size_t q = 0; q < mesh.quads.size(); ++q) {
        INFO("quad " << q);
        CHECK(quad_edge_ratio(mesh.corners(q)) <= std::max(kSmoothingEdgeRatio, before[q]) * (1 + 1e-12));
        degenerate_before += before[q] > kSmoothingEdgeRatio ? 1 : 0;
      }
    }
  }
  CHECK(degenerate_before > 0);  // some quads started past the limit: they may keep, not raise, theirs
}
