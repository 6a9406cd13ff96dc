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
    // Boundary nodes stay exactly where they were.
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        if (i > 0 && i < n && j > 0 && j < n) continue;
        const size_t v = static_cast<size_t>(j * (n + 1) + i);
        CHECK(mesh.nodes[v] == before.nodes[v]);
      }
    }
  }
}

TEST_CASE("the worst-first pass raises the minimum that the sweeps leave", "[mesh][smoothing]") {
  // Grids whose boundary nodes bunch towards one corner (as where a short block side carries many
  // intervals) and whose interior is jittered: the sweeps' four candidate positions stop short; the
  // pattern search on the worst quads' corners goes further, never lowering the minimum and never
  // moving a boundary node.
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
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        if (i > 0 && i < n && j > 0 && j < n) continue;
        const size_t v = static_cast<size_t>(j * (n + 1) + i);
        CHECK(mesh.nodes[v] == sweeps_only.nodes[v]);
      }
    }
  }
  CHECK(better >= 15);
}
