// Swept solids meshed with hexahedra through core/api: generated faces (rectangle unions with and
// without holes, general polygons) extruded normally and obliquely, some turned into tilted planes;
// every mesh conformal by the independent check, volumes exact, the prism blocks conformal.
#include "support/catch_torch.h"

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/api/solid_meshing.h"
#include "core/common/error.h"
#include "core/data/arc_generator.h"
#include "core/geometry/occt_face.h"
#include "core/mesh/hex_conformity.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

struct Extrusion {
  TopoDS_Shape solid;
  double volume = 0.0;  // the face's area times the height
  bool normal = true, rectilinear = true;
};

// face swept by (dx, dy, h), then turned about a random axis when turn.
Extrusion extrude(const TopoDS_Face& face, double dx, double dy, double h, bool turn, std::mt19937_64& rng) {
  Extrusion e;
  GProp_GProps area;
  BRepGProp::SurfaceProperties(face, area);
  e.volume = area.Mass() * h;
  e.normal = dx == 0 && dy == 0;
  e.solid = BRepPrimAPI_MakePrism(face, gp_Vec(dx, dy, h)).Shape();
  if (turn) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    gp_Trsf t;
    t.SetRotation(gp_Ax1(gp_Pnt(u(rng) * 5, u(rng) * 5, u(rng) * 5), gp_Dir(u(rng), u(rng), 1.5)), 0.3 + u(rng));
    e.solid = BRepBuilderAPI_Transform(e.solid, t, true).Shape();
  }
  return e;
}

DecomposeSettings greedy() {
  DecomposeSettings s;
  s.policy = "greedy";
  return s;
}

// The prisms share their inner faces: every face of the compound lies on one or two blocks, and as many
// lie on two as the blocks' faces minus the compound's distinct faces.
void check_blocks(const SolidMeshing& m, double epsilon = 1e-9) {
  const PrismBlocks blocks = solid_meshing_blocks(m);
  REQUIRE(blocks.solids.size() == m.blocks());
  double volume = 0.0;
  int block_faces = 0;
  for (const TopoDS_Solid& s : blocks.solids) {
    GProp_GProps p;
    BRepGProp::VolumeProperties(s, p);
    volume += p.Mass();
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(s, TopAbs_FACE, faces);
    block_faces += faces.Extent();
  }
  CHECK(volume == Approx(m.solid.volume).epsilon(epsilon));
  TopTools_IndexedDataMapOfShapeListOfShape face_solids;
  TopExp::MapShapesAndUniqueAncestors(blocks.compound, TopAbs_FACE, TopAbs_SOLID, face_solids);
  int shared = 0;
  for (int f = 1; f <= face_solids.Extent(); ++f) {
    CHECK(face_solids(f).Extent() <= 2);
    shared += face_solids(f).Extent() == 2;
  }
  CHECK(block_faces - face_solids.Extent() == shared);
  if (m.blocks() > 1) CHECK(shared >= static_cast<int>(m.blocks()) - 1);
  CHECK(BRepCheck_Analyzer(blocks.compound).IsValid());
}

}  // namespace

TEST_CASE("swept solids of generated faces: conformal, exact volumes, SJ 1 for normal rectilinear ones", "[solid][hex][api]") {
  std::mt19937_64 rng(20261130);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0, blocks_checked = 0;
  for (const bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    options.max_rects = 8;
    const auto shapes = test::generated_shapes(100, holes ? 71 : 70, options);
    for (size_t k = 0; k < shapes.size(); ++k) {
      const TopoDS_Face face = occt_face_from_polygon(shapes[k].polygon, 0.0, true);
      const bool oblique = k % 3 == 1, turn = k % 4 == 2;
      const double h = 2 + 6 * u(rng);
      const Extrusion e = extrude(face, oblique ? 3 * u(rng) - 1.5 : 0, oblique ? 2 * u(rng) - 1 : 0, h, turn, rng);
      const SweptSolid solid = swept_solid_from_shape(e.solid, "extrusion " + std::to_string(k));
      SolidMeshOptions o;
      o.cap.size = 1.0;
      if (k % 5 == 3) o.grading = 1.3;
      const SolidMeshing m = mesh_swept_solid(solid, greedy(), o);
      INFO("shape " << k << (holes ? " with holes" : "") << (oblique ? ", oblique" : "") << (turn ? ", turned" : "") << ": "
                    << m.conformity.problem);
      CHECK(m.conformity.conformal);
      CHECK(m.conformity.inverted_hexes == 0);
      CHECK(m.conformity.hex_volume == Approx(e.volume).epsilon(1e-9));
      CHECK(solid.volume == Approx(e.volume).epsilon(1e-9));
      CHECK(m.mesh.layers == std::max(1, static_cast<int>(std::lround(solid.sweep.Magnitude()))));
      CHECK(m.mesh.hexes.size() == m.cap.result.mesh.quads.size() * static_cast<size_t>(m.mesh.layers));
      if (e.normal) {
        CHECK(m.quality.min_scaled_jacobian >= 1.0 - 1e-12);
        CHECK(m.quality.irregular_edges == 0);
      } else {
        CHECK(m.quality.min_scaled_jacobian > 0.0);
        CHECK(m.quality.min_scaled_jacobian < 1.0);
      }
      if (k % 4 == 0) {
        check_blocks(m);
        ++blocks_checked;
      }
      ++checked;
    }
  }
  CHECK(checked == 200);
  CHECK(blocks_checked == 50);
}

TEST_CASE("swept solids of general faces (edges at any angle): conformal, exact volumes", "[solid][hex][api]") {
  std::mt19937_64 rng(7);
  int k = 0;
  for (const GeneralKind kind : {GeneralKind::Polygon, GeneralKind::Chamfered, GeneralKind::Turned}) {
    for (const bool holes : {false, true}) {
      const RectilinearPolygon polygon = test::general_polygon(static_cast<std::uint64_t>(300 + k), kind, holes);
      const TopoDS_Face face = occt_face_from_polygon(polygon, 1.0, true);
      const Extrusion e = extrude(face, k % 2 ? 0.7 : 0, 0, 3.5, k == 2, rng);
      const SweptSolid solid = swept_solid_from_shape(e.solid, "general " + std::to_string(k));
      SolidMeshOptions o;
      o.layers = 3;
      const SolidMeshing m = mesh_swept_solid(solid, DecomposeSettings{}, o);
      INFO("general face " << k << ": " << m.conformity.problem);
      CHECK(m.cap.general() == (kind != GeneralKind::Turned));
      CHECK(m.conformity.conformal);
      // The cap's nodes lie on its lattice (within its quantum, as the 2-D check allows).
      CHECK(m.conformity.hex_volume == Approx(e.volume).epsilon(1e-6));
      CHECK(m.mesh.layers == 3);
      if (k < 2) check_blocks(m, 1e-6);
      ++k;
    }
  }
}

TEST_CASE("swept solids whose cap has a vertex between two edges in line: a column of nodes up the split side",
          "[solid][hex][api]") {
  // A rectangle and a pentagon whose bottom edge is two edges meeting at (3.37, 0), extruded: the side
  // face below that edge is two faces, and the hexahedra must meet both (the cap's mesh had no node at
  // the vertex, and the sweep failed its conformity check: two side faces' quads did not add up).
  std::mt19937_64 rng(11);
  const std::vector<std::vector<std::pair<double, double>>> caps = {{{0, 0}, {3.37, 0}, {10, 0}, {10, 4}, {0, 4}},
                                                                    {{0, 0}, {3.37, 0}, {10, 0}, {12, 5}, {1, 4}}};
  for (size_t c = 0; c < caps.size(); ++c) {
    BRepBuilderAPI_MakePolygon wire;
    for (const auto& [x, y] : caps[c]) wire.Add(gp_Pnt(x, y, 0));
    wire.Close();
    const Extrusion e = extrude(BRepBuilderAPI_MakeFace(wire.Wire()).Face(), 0, 0, 3, false, rng);
    const SweptSolid solid = swept_solid_from_shape(e.solid, "split side " + std::to_string(c));
    SolidMeshOptions o;
    o.cap.size = 1.0;
    const SolidMeshing m = mesh_swept_solid(solid, greedy(), o);
    INFO("cap " << c << ": " << m.conformity.problem);
    CHECK(m.cap.general() == (c == 1));
    CHECK(m.conformity.conformal);
    CHECK(m.conformity.hex_volume == Approx(e.volume).epsilon(1e-6));
  }
}

TEST_CASE("swept solids split across the sweep (fused without refining): the layers meet the splits, quads tagged by face",
          "[solid][hex][api]") {
  // Boxes stacked and side by side, three slabs, an L stacked and drilled plates stacked: every side
  // face split where the parts meet. The sweep failed its conformity check on these (a column of side
  // quads tagged with the face at the bottom cap): now every split is a station, and the side quads
  // of each stretch are tagged with the face there, which the independent check adds up per face.
  struct Case {
    std::string name;
    TopoDS_Shape shape;
    std::vector<double> heights;  // the splits' coordinate along the sweep's axis (z, or x for the row)
    int axis;                     // 2: z, 0: x
  };
  const TopoDS_Face l = occt_face_from_polygon(test::polygon_of({{0, 0}, {8, 0}, {8, 3}, {3, 3}, {3, 7}, {0, 7}}), 0, true);
  const TopoDS_Face plate = plate_with_holes(20, 10, {{7, 5, 2}});
  auto fuse = [](const std::vector<TopoDS_Shape>& parts) {
    TopoDS_Shape out = parts[0];
    for (size_t k = 1; k < parts.size(); ++k) out = BRepAlgoAPI_Fuse(out, parts[k]).Shape();
    return out;
  };
  auto up = [](const TopoDS_Shape& s, double z) {
    gp_Trsf t;
    t.SetTranslation(gp_Vec(0, 0, z));
    return BRepBuilderAPI_Transform(s, t, true).Shape();
  };
  const std::vector<Case> cases{
      {"stacked", fuse({BRepPrimAPI_MakeBox(10, 4, 1.3).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 1.3), 10, 4, 1.7).Shape()}), {1.3}, 2},
      {"side by side", fuse({BRepPrimAPI_MakeBox(10, 4, 3).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 0), 4, 4, 3).Shape()}), {10}, 0},
      {"three slabs",
       fuse({BRepPrimAPI_MakeBox(10, 4, 1).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 1), 10, 4, 1).Shape(),
             BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 2), 10, 4, 1).Shape()}),
       {1, 2},
       2},
      {"L stacked", fuse({BRepPrimAPI_MakePrism(l, gp_Vec(0, 0, 2)).Shape(), up(BRepPrimAPI_MakePrism(l, gp_Vec(0, 0, 1)).Shape(), 2)}), {2}, 2},
      {"drilled plates stacked",
       fuse({BRepPrimAPI_MakePrism(plate, gp_Vec(0, 0, 2)).Shape(), up(BRepPrimAPI_MakePrism(plate, gp_Vec(0, 0, 3)).Shape(), 2)}),
       {2},
       2},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    GProp_GProps volume;
    BRepGProp::VolumeProperties(c.shape, volume);
    const SweptSolid solid = swept_solid_from_shape(c.shape, c.name);
    REQUIRE(solid.splits.size() == c.heights.size());
    SolidMeshOptions o;
    o.cap.size = 0.5;
    const SolidMeshing m = mesh_swept_solid(solid, DecomposeSettings{}, o);
    INFO(m.conformity.problem);
    CHECK(m.conformity.conformal);
    CHECK(m.conformity.hex_volume == Approx(volume.Mass()).epsilon(1e-6));
    // A layer of nodes at every split.
    for (double h : c.heights) {
      const auto at = std::count_if(m.mesh.nodes.begin(), m.mesh.nodes.end(),
                                    [&](const Point3& p) { return std::fabs(p[static_cast<size_t>(c.axis)] - h) < 1e-9; });
      CHECK(static_cast<size_t>(at) == m.cap.result.mesh.nodes.size());
    }
    // Every face of the solid has quads, as many as its area holds (the check adds up their areas).
    std::vector<int> quads(solid.faces.size(), 0);
    for (const BoundaryQuad& b : m.mesh.boundary) ++quads[static_cast<size_t>(b.face - 1)];
    CHECK(std::count(quads.begin(), quads.end(), 0) == 0);
    check_blocks(m, 1e-6);
  }
  // The requested layers are shared by the stretches' lengths, at least one each.
  SolidMeshOptions o;
  o.cap.size = 1.0;
  o.layers = 1;
  const SweptSolid stacked = swept_solid_from_shape(cases[0].shape, "stacked");
  SolidMeshing m = mesh_swept_solid(stacked, greedy(), o);
  CHECK(m.mesh.layers == 2);
  CHECK(m.conformity.conformal);
  o.layers = 10;
  o.grading = 1.5;
  m = mesh_swept_solid(stacked, greedy(), o);
  CHECK(m.mesh.layers == 10);
  CHECK(m.conformity.conformal);
}

TEST_CASE("swept solids with cylinder sides (drilled holes, rounded edges): conformal, nodes on the cylinders",
          "[solid][hex][api][arc]") {
  std::mt19937_64 rng(11);
  const TopoDS_Face plate = plate_with_holes(12, 8, {{3, 4, 1.5}, {8.5, 3.5, 1}});
  const TopoDS_Face rounded = filleted_polygon(RectilinearPolygon{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}}, 1.5);
  struct Case {
    TopoDS_Face face;
    bool turn;
    size_t cylinders;
  };
  const std::vector<Case> cases{{plate, false, 2}, {plate, true, 2}, {rounded, false, 4}, {disk(1, 2, 3), true, 1}};
  for (size_t k = 0; k < cases.size(); ++k) {
    CAPTURE(k);
    const Extrusion e = extrude(cases[k].face, 0, 0, 2.5, cases[k].turn, rng);
    const SweptSolid solid = swept_solid_from_shape(e.solid, "arcs " + std::to_string(k));
    size_t cylinders = 0;
    for (const TopoDS_Face& f : solid.faces) cylinders += !f.IsNull() && surface_name(f) == "cylinder";
    CHECK(cylinders == cases[k].cylinders);
    SolidMeshOptions o;
    o.layers = 3;
    const SolidMeshing m = mesh_swept_solid(solid, DecomposeSettings{}, o);
    INFO(m.conformity.problem);
    REQUIRE(m.conformity.conformal);
    CHECK(m.mesh.layers == 3);
    // The hexahedra alone miss (rounded edges) or cover beyond (holes) the segments between their
    // chords and the arcs: the cap's curved gap times the height.
    const double gap = m.cap.result.conformity.curved_gap_area;
    double raw = 0.0;
    for (size_t h = 0; h < m.mesh.hexes.size(); ++h) raw += hex_volume(m.mesh.corners(h));
    CHECK(raw + gap * 2.5 == Approx(e.volume).epsilon(1e-6));
    CHECK(m.conformity.hex_volume == Approx(e.volume).epsilon(1e-6));
    check_blocks(m, 1e-6);
    // A cylinder is smooth: two hexahedra along the edge between two of its chords (at 165 or 195
    // degrees) and at its tangent joins with planes are structured, so the irregular edges are the
    // cap's irregular vertices swept, all inside.
    CHECK(m.quality.irregular_edges == m.quality.irregular_interior_edges);
    if (k == 0) {
      // Every layer's nodes on the holes' circles: at least the holes' 24-chord polygons' directions.
      int on = 0;
      for (const Point3& p : m.mesh.nodes) {
        for (const auto& [x, y, r] : {std::array<double, 3>{3, 4, 1.5}, std::array<double, 3>{8.5, 3.5, 1}}) {
          on += std::fabs(std::hypot(p[0] - x, p[1] - y) - r) < 1e-9 * r;
        }
      }
      CHECK(on >= 2 * 24 * 4);
    }
  }
}

TEST_CASE("a swept solid whose every surface and curve is a B-spline meshes as its canonical twin", "[solid][hex][api][arc]") {
  // As CATIA writes a drilled plate: its holes' walls B-spline surfaces (edge_curve.h, face_cylinder),
  // its circles B-splines; its areas and volume integrated precisely (kPropertiesPrecision).
  const TopoDS_Shape canonical = BRepPrimAPI_MakePrism(plate_with_holes(12, 8, {{3, 4, 1.5}, {8.5, 3.5, 1}}), gp_Vec(0, 0, 2.5)).Shape();
  const TopoDS_Shape nurbs = BRepBuilderAPI_NurbsConvert(canonical, true).Shape();
  const SweptSolid solid = swept_solid_from_shape(nurbs, "NURBS plate");
  size_t splines = 0;
  for (const TopoDS_Face& f : solid.faces) splines += !f.IsNull() && surface_name(f) == "B-spline surface";
  CHECK(splines >= 6);
  CHECK(solid.sweep.Magnitude() == Approx(2.5));
  SolidMeshOptions o;
  o.layers = 3;
  const SolidMeshing m = mesh_swept_solid(solid, DecomposeSettings{}, o);
  INFO(m.conformity.problem);
  CHECK(m.conformity.conformal);
  const SolidMeshing reference = mesh_swept_solid(swept_solid_from_shape(canonical, "plate"), DecomposeSettings{}, o);
  CHECK(m.mesh.hexes.size() == reference.mesh.hexes.size());
  CHECK(m.conformity.hex_volume == Approx(reference.conformity.hex_volume).epsilon(1e-6));
}

TEST_CASE("swept solid requests: layers, grading and sizes that cannot be met are input errors", "[solid][hex][api]") {
  const TopoDS_Face face = occt_face_from_polygon(test::polygon_of({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}), 0, true);
  const SweptSolid solid = swept_solid_from_shape(BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 3)).Shape(), "l");
  SolidMeshOptions o;
  o.grading = -1;
  CHECK_THROWS_AS(mesh_swept_solid(solid, greedy(), o), InputError);
  o = SolidMeshOptions{};
  o.cap.size = 1e-3;  // 4000 x 4000 x 3000 / 4 hexahedra
  CHECK_THROWS_WITH(mesh_swept_solid(solid, greedy(), o), Catch::Matchers::Contains("limit") ||
                                                          Catch::Matchers::Contains("hexahedra"));
  o = SolidMeshOptions{};
  o.layers = 4;
  o.grading = 2.0;
  const SolidMeshing m = mesh_swept_solid(solid, greedy(), o);
  CHECK(m.mesh.layers == 4);
  CHECK(m.conformity.conformal);
  CHECK(m.default_size);
  CHECK(m.target_size == Approx(4.0 / 20));
  const nlohmann::json report = solid_meshing_json("l.brep", m);
  CHECK(report["kind"] == "solid");
  CHECK(report["hexahedra"] == m.mesh.hexes.size());
  CHECK(report["conformal"] == true);
  CHECK(report["quality"]["irregular_edges"] == 0);
  CHECK(report["cap"]["quads"] == m.cap.result.mesh.quads.size());
  CHECK(report["sweep_angle"].get<double>() == Approx(0.0).margin(1e-9));
  const std::string svg = solid_meshing_svg(m, "l | hexahedra");
  CHECK(svg.find("<polygon") != std::string::npos);
}
