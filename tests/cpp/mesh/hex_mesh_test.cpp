// Sweeping a quad mesh into hexahedra, their quality (Verdict's measures) and the independent
// conformity check, on hand-made meshes whose answers are known.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/common/error.h"
#include "core/mesh/hex_conformity.h"
#include "core/mesh/hex_mesh.h"
#include "core/mesh/hex_quality.h"

using namespace autoblock;

namespace {

// An nx x ny grid of unit quads on [0,nx] x [0,ny], counter-clockwise; quads with x < split in block 0.
QuadMesh grid_mesh(int nx, int ny, int split) {
  QuadMesh m;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) m.nodes.push_back({double(i), double(j)});
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      m.quads.push_back({a, a + 1, a + nx + 2, a + nx + 1});
      m.quad_block.push_back(i < split ? 0 : 1);
    }
  }
  m.blocks = split < nx ? 2 : 1;
  return m;
}

// The solid's faces for the grid swept along sweep: 1 bottom, 2 top, 3 y = 0, 4 x = nx, 5 y = ny, 6 x = 0.
SweepFrame grid_frame(int nx, int ny, Point3 sweep) {
  SweepFrame w;
  w.sweep = sweep;
  w.bottom_face = 1;
  w.top_face = 2;
  w.side_face = [nx, ny](const Point3& a, const Point3& b, int) {
    const double x = (a[0] + b[0]) / 2, y = (a[1] + b[1]) / 2;
    if (y == 0) return 3;
    if (x == nx) return 4;
    if (y == ny) return 5;
    return x == 0 ? 6 : 0;
  };
  return w;
}

// The grid's box swept by sweep: face areas as numbered above.
std::vector<double> grid_face_areas(int nx, int ny, Point3 s) {
  auto len = [](double a, double b) { return std::sqrt(a * a + b * b); };
  // Side y = 0 is the edge (nx, 0, 0) swept: area |(nx,0,0) x s|.
  return {double(nx * ny), double(nx * ny), nx * len(s[2], s[1]), ny * len(s[2], s[0]), nx * len(s[2], s[1]),
          ny * len(s[2], s[0])};
}

// The solid's figures for the conformity check (no perimeters, no tolerance: exact meshes).
SolidFigures figures(double volume, double area, const std::vector<double>& faces) {
  SolidFigures f;
  f.volume = volume;
  f.area = area;
  f.face_areas = faces;
  return f;
}

}  // namespace

TEST_CASE("layer stations: uniform and geometric", "[mesh][hex]") {
  CHECK(layer_stations(4, 1.0) == std::vector<double>{0, 0.25, 0.5, 0.75, 1});
  const std::vector<double> s = layer_stations(3, 2.0);  // thicknesses 1, 2, 4 of 7
  REQUIRE(s.size() == 4);
  CHECK(s[1] == Approx(1.0 / 7));
  CHECK(s[2] == Approx(3.0 / 7));
  CHECK(s[3] == 1.0);
  CHECK(layer_stations(1, 3.0) == std::vector<double>{0, 1});
  CHECK_THROWS_AS(layer_stations(0, 1.0), InputError);
  CHECK_THROWS_AS(layer_stations(2, -1.0), InputError);
  CHECK_THROWS_AS(layer_stations(2, std::nan("")), InputError);
}

TEST_CASE("layer stations with splits: a station at every split, the layers shared by length, one at least", "[mesh][hex]") {
  CHECK(layer_stations(4, 1.0, {}) == layer_stations(4, 1.0));
  // Stretches 0.4 and 0.6 of 5 layers: 2 and 3.
  std::vector<double> s = layer_stations(5, 1.0, {0.4});
  REQUIRE(s.size() == 6);
  CHECK(s[1] == Approx(0.2));
  CHECK(s[2] == 0.4);
  CHECK(s[3] == Approx(0.6));
  CHECK(s[5] == 1.0);
  // One layer wanted over two stretches: each gets one.
  CHECK(layer_stations(1, 1.0, {0.65}) == std::vector<double>{0, 0.65, 1});
  // 6 layers over 0.1, 0.45, 0.45: shares 0.6, 2.7, 2.7 -> 1 (raised), then 2 + 2 and one more to the
  // first of the equal remainders: 1, 3, 2.
  s = layer_stations(6, 1.0, {0.1, 0.55});
  REQUIRE(s.size() == 7);
  CHECK(s[1] == 0.1);
  CHECK(s[2] == Approx(0.25));
  CHECK(s[4] == 0.55);
  CHECK(s[5] == Approx(0.775));
  // Graded within each stretch: thicknesses 1 and 2 of 3 in each half.
  s = layer_stations(4, 2.0, {0.5});
  REQUIRE(s.size() == 5);
  CHECK(s[1] == Approx(1.0 / 6));
  CHECK(s[2] == 0.5);
  CHECK(s[3] == Approx(0.5 + 1.0 / 6));
  CHECK(std::is_sorted(s.begin(), s.end()));
  CHECK_THROWS_AS(layer_stations(0, 1.0, {0.5}), InputError);
  CHECK_THROWS_AS(layer_stations(2, 0.0, {0.5}), InputError);
}

TEST_CASE("a swept grid split across the sweep: side quads tagged by the stretch they lie in", "[mesh][hex]") {
  // The grid's box with its side y = 0 split at a third of the height: face 3 below, face 7 above.
  const QuadMesh cap = grid_mesh(2, 1, 2);
  SweepFrame w = grid_frame(2, 1, {0, 0, 3});
  w.splits = {1.0 / 3};
  const auto side = w.side_face;
  w.side_face = [side](const Point3& a, const Point3& b, int stretch) {
    const int face = side(a, b, stretch);
    return face == 3 && stretch == 1 ? 7 : face;
  };
  const HexMesh m = sweep_quad_mesh(cap, w, layer_stations(3, 1.0, w.splits));
  REQUIRE(m.layers == 3);
  std::map<int, int> quads;
  for (const BoundaryQuad& b : m.boundary) ++quads[b.face];
  CHECK(quads[3] == 2);  // the bottom layer's two quads on y = 0
  CHECK(quads[7] == 4);
  CHECK(quads[4] == 3);
  std::vector<double> areas = grid_face_areas(2, 1, {0, 0, 3});
  areas[2] = 2;
  areas.push_back(4);
  CHECK(check_hex_conformity(m, figures(6, 22, areas)).conformal);
  // Tagged as if the side were one face (the stretches ignored), the split solid's faces do not add up.
  CHECK_FALSE(check_hex_conformity(sweep_quad_mesh(cap, grid_frame(2, 1, {0, 0, 3}), layer_stations(3, 1.0)),
                                   figures(6, 22, areas)).conformal);
}

TEST_CASE("a swept grid: nodes, hexahedra, blocks, boundary, quality 1 and no irregular edge", "[mesh][hex]") {
  const QuadMesh cap = grid_mesh(3, 2, 1);
  const Point3 sweep{0, 0, 2};
  const HexMesh m = sweep_quad_mesh(cap, grid_frame(3, 2, sweep), layer_stations(4, 1.0));
  CHECK(m.nodes.size() == 12 * 5);
  CHECK(m.hexes.size() == 6 * 4);
  CHECK(m.layers == 4);
  CHECK(m.blocks == 2);
  CHECK(std::count(m.hex_block.begin(), m.hex_block.end(), 0) == 2 * 4);
  CHECK(m.nodes.back() == Point3{3, 2, 2});
  CHECK(m.boundary.size() == 6 + 6 + 4 * (3 + 2 + 3 + 2));
  const HexMeshQuality q = hex_mesh_quality(m);
  CHECK(q.min_scaled_jacobian == Approx(1.0).margin(1e-15));
  CHECK(q.max_skew == Approx(0.0).margin(1e-15));
  CHECK(q.max_aspect_ratio == Approx(2.0));  // 1 x 1 x 0.5
  CHECK(q.irregular_edges == 0);
  // Inside: the vertical edges over the cap's 2 interior nodes (4 layers each), and the cap's 7
  // interior edges at the 3 inner stations.
  CHECK(q.interior_edges == 2 * 4 + 7 * 3);
  CHECK(q.edges == 17 * 5 + 12 * 4);
  const HexConformity c = check_hex_conformity(m, figures(3 * 2 * 2, 2 * 6 + 2 * (3 * 2 + 2 * 2), grid_face_areas(3, 2, sweep)));
  INFO(c.problem);
  CHECK(c.conformal);
  CHECK(c.inverted_hexes == 0);
  CHECK(c.hex_volume == Approx(12.0));
  CHECK(c.boundary_faces == static_cast<int>(m.boundary.size()));
}

TEST_CASE("an oblique sweep: positive hexahedra, scaled Jacobian the cosine, reversed frames too", "[mesh][hex]") {
  const QuadMesh cap = grid_mesh(2, 2, 2);
  for (double dz : {1.0, -1.0}) {
    const Point3 sweep{1, 0, dz};
    const HexMesh m = sweep_quad_mesh(cap, grid_frame(2, 2, sweep), layer_stations(3, 1.5));
    const HexMeshQuality q = hex_mesh_quality(m);
    CHECK(q.min_scaled_jacobian == Approx(1 / std::sqrt(2.0)));
    CHECK(q.max_skew == Approx(1 / std::sqrt(2.0)));
    CHECK(q.irregular_edges == 0);  // its 45 and 135 degree edges are convex: one hexahedron each
    const HexConformity c = check_hex_conformity(m, figures(4.0, 0.0, {}));
    CHECK(c.inverted_hexes == 0);
    CHECK(c.hex_volume == Approx(4.0));
  }
}

TEST_CASE("hexahedron quality: a box, a sheared one, an inverted one", "[mesh][hex]") {
  std::array<Point3, 8> box{{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 3}, {2, 0, 3}, {2, 1, 3}, {0, 1, 3}}};
  HexQuality q = hex_quality(box);
  CHECK(q.scaled_jacobian == 1.0);
  CHECK(q.aspect_ratio == 3.0);
  CHECK(q.skew == 0.0);
  CHECK(hex_volume(box) == Approx(6.0));
  std::array<Point3, 8> flipped = box;
  std::swap(flipped[1], flipped[3]);
  std::swap(flipped[5], flipped[7]);
  CHECK(hex_quality(flipped).scaled_jacobian == Approx(-1.0));
  CHECK(hex_volume(flipped) == Approx(-6.0));
  std::array<Point3, 8> collapsed = box;
  collapsed[6] = collapsed[2];
  CHECK(hex_quality(collapsed).scaled_jacobian <= 0.0);
}

TEST_CASE("the hexahedral conformity check finds holes, doubles, flips and wrong tags", "[mesh][hex]") {
  const QuadMesh cap = grid_mesh(2, 2, 1);
  const Point3 sweep{0, 0, 1};
  const HexMesh good = sweep_quad_mesh(cap, grid_frame(2, 2, sweep), layer_stations(2, 1.0));
  const double volume = 4.0, area = 2 * 4.0 + 4 * 2.0;
  const std::vector<double> faces = grid_face_areas(2, 2, sweep);
  REQUIRE(check_hex_conformity(good, figures(volume, area, faces)).conformal);
  SECTION("a missing hexahedron (a corner one: the boundary area stays, the volume does not)") {
    HexMesh m = good;
    m.hexes.erase(m.hexes.begin() + 1);
    m.hex_block.erase(m.hex_block.begin() + 1);
    const HexConformity c = check_hex_conformity(m, figures(volume, area, faces));
    CHECK_FALSE(c.conformal);
    CHECK_THAT(c.problem, Catch::Matchers::Contains("volume 3.5 is not the solid's 4"));
  }
  SECTION("a doubled hexahedron") {
    HexMesh m = good;
    m.hexes.push_back(m.hexes[0]);
    m.hex_block.push_back(0);
    const HexConformity c = check_hex_conformity(m, figures(volume, area, faces));
    CHECK_FALSE(c.conformal);
    CHECK(c.overused_faces == 3);     // its faces inside: with its twin and its neighbour
    CHECK(c.misoriented_faces == 3);  // its faces on the boundary: twice, the same way
  }
  SECTION("an inverted hexahedron") {
    HexMesh m = good;
    auto& h = m.hexes[0];
    std::swap(h[1], h[3]);
    std::swap(h[5], h[7]);
    CHECK(check_hex_conformity(m, figures(volume, area, faces)).inverted_hexes == 1);
  }
  SECTION("a boundary quad tagged with the wrong face") {
    HexMesh m = good;
    for (BoundaryQuad& b : m.boundary) {
      if (b.face == 3) {
        b.face = 4;
        break;
      }
    }
    const HexConformity c = check_hex_conformity(m, figures(volume, area, faces));
    CHECK_FALSE(c.conformal);
    CHECK(c.mismatched_faces == 2);
  }
  SECTION("the wrong solid volume") { CHECK_FALSE(check_hex_conformity(good, figures(4.5, area, faces)).conformal); }
}
