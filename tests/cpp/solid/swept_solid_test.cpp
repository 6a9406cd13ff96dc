// Swept solids: caps and sweep found on good solids (normal, oblique, in any plane, a closed shell),
// and one clear error per class of bad solid, naming the face.
#include <catch2/catch.hpp>

#include <cmath>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

#include "core/common/error.h"
#include "core/geometry/occt_face.h"
#include "core/solid/swept_solid.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// The L-shaped face (0,0) (4,0) (4,2) (2,2) (2,4) (0,4) at z = 0, swept by (dx, dy, dz).
TopoDS_Shape l_prism(double dx, double dy, double dz) {
  const TopoDS_Face face =
      occt_face_from_polygon(test::polygon_of({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}), 0, true);
  return BRepPrimAPI_MakePrism(face, gp_Vec(dx, dy, dz)).Shape();
}

TopoDS_Shape moved(const TopoDS_Shape& shape, const gp_Trsf& t) { return BRepBuilderAPI_Transform(shape, t, true).Shape(); }

// A closed polyhedron: points, and faces as point indices (each face planar, boundaries matching).
TopoDS_Shape polyhedron(const std::vector<gp_Pnt>& points, const std::vector<std::vector<int>>& faces) {
  BRepBuilderAPI_Sewing sewing;
  for (const auto& face : faces) {
    BRepBuilderAPI_MakePolygon polygon;
    for (int k : face) polygon.Add(points[static_cast<size_t>(k)]);
    polygon.Close();
    sewing.Add(BRepBuilderAPI_MakeFace(polygon.Wire(), true).Face());
  }
  sewing.Perform();
  TopExp_Explorer it(sewing.SewedShape(), TopAbs_SHELL);
  REQUIRE(it.More());
  BRepBuilderAPI_MakeSolid solid(TopoDS::Shell(it.Current()));
  REQUIRE(solid.IsDone());
  return solid.Solid();
}

// Two quadrilaterals at z = 0 and z = 1 joined by four planar sides.
TopoDS_Shape prismatoid(const std::vector<gp_Pnt>& bottom, const std::vector<gp_Pnt>& top) {
  std::vector<gp_Pnt> points = bottom;
  points.insert(points.end(), top.begin(), top.end());
  return polyhedron(points, {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
}

std::string error_of(const TopoDS_Shape& shape) {
  try {
    swept_solid_from_shape(shape, "part.step");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void check_error(const TopoDS_Shape& shape, const std::string& expected) {
  const std::string message = error_of(shape);
  INFO(message);
  CHECK_THAT(message, StartsWith("part.step: ") && Contains(expected));
  CHECK(message.find('\n') == std::string::npos);
}

}  // namespace

TEST_CASE("swept solids: the caps and the sweep of normal and oblique extrusions", "[solid]") {
  SECTION("a normal extrusion of an L") {
    const SweptSolid s = swept_solid_from_shape(l_prism(0, 0, 3), "l");
    CHECK(s.faces.size() == 8);
    CHECK(s.sweep.Magnitude() == Approx(3.0));
    CHECK(std::fabs(s.sweep.Z()) == Approx(3.0));
    CHECK(s.volume == Approx(12.0 * 3.0));
    CHECK(s.area == Approx(2 * 12.0 + 16.0 * 3.0));
    CHECK(s.bottom != s.top);
    CHECK_FALSE(s.cap.is_general());
    CHECK(s.cap.planar.polygon.outer.size() == 6);
  }
  SECTION("an oblique extrusion: the sweep is the translation, not the normal") {
    const SweptSolid s = swept_solid_from_shape(l_prism(1, 0.5, 3), "l");
    const double sign = s.sweep.Z() > 0 ? 1 : -1;
    CHECK(s.sweep.X() == Approx(sign * 1.0));
    CHECK(s.sweep.Y() == Approx(sign * 0.5));
    CHECK(s.volume == Approx(36.0));
  }
  SECTION("turned into another plane, and given as a closed shell") {
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(1, 2, 3), gp_Dir(1, 2, 2)), 0.7);
    const TopoDS_Shape solid = moved(l_prism(0, 0, 3), turn);
    const SweptSolid s = swept_solid_from_shape(solid, "turned");
    CHECK(s.sweep.Magnitude() == Approx(3.0));
    CHECK_FALSE(s.cap.is_general());  // rectilinear in its own frame
    TopExp_Explorer it(solid, TopAbs_SHELL);
    const SweptSolid shell = swept_solid_from_shape(it.Current(), "shell");
    CHECK(shell.volume == Approx(36.0));
    CHECK(holds_one_solid(it.Current()));
  }
  SECTION("a box: the largest caps") {
    const SweptSolid s = swept_solid_from_shape(BRepPrimAPI_MakeBox(2, 3, 4).Shape(), "box");
    CHECK(s.sweep.Magnitude() == Approx(2.0));  // the caps are the 3 x 4 faces
  }
}

TEST_CASE("swept solids: one clear error per class, naming the face", "[solid][errors]") {
  SECTION("more than one solid") {
    TopoDS_Compound two;
    BRep_Builder builder;
    builder.MakeCompound(two);
    builder.Add(two, BRepPrimAPI_MakeBox(1, 1, 1).Shape());
    builder.Add(two, BRepPrimAPI_MakeBox(gp_Pnt(3, 0, 0), 1, 1, 1).Shape());
    check_error(two, "the file holds 2 solids; a swept solid is exactly one solid");
    CHECK_FALSE(holds_one_solid(two));
  }
  SECTION("an open shell") {
    TopoDS_Shell shell;
    BRep_Builder builder;
    builder.MakeShell(shell);
    int k = 0;
    for (TopExp_Explorer it(l_prism(0, 0, 3), TopAbs_FACE); it.More(); it.Next()) {
      if (++k < 8) builder.Add(shell, it.Current());  // the last face left out
    }
    check_error(shell, "the shell is open: face ");
    check_error(shell, " has a free edge from (");
  }
  SECTION("a cavity") {
    const TopoDS_Shape hollow =
        BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(4, 4, 4).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(1, 1, 1), 2, 2, 2).Shape()).Shape();
    check_error(hollow, "the solid has 2 shells (a cavity inside it)");
  }
  SECTION("a cylinder across the sweep") {
    // A box drilled along Z and along X (apart): every pair of caps has a hole across its sweep.
    TopoDS_Shape part = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(10, 6, 4).Shape(),
                                        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(7, 1.2, -1), gp_Dir(0, 0, 1)), 0.6, 6).Shape())
                            .Shape();
    part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-1, 4.5, 2), gp_Dir(1, 0, 0)), 0.8, 12).Shape()).Shape();
    check_error(part, ", a cylinder, does not run along the sweep ");
    check_error(part, "a swept solid's side faces run along the sweep");
    // Either hole alone is a sweep along its axis.
    const TopoDS_Shape drilled = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(10, 6, 4).Shape(),
                                                 BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-1, 4.5, 2), gp_Dir(1, 0, 0)), 0.8, 12).Shape())
                                     .Shape();
    const SweptSolid solid = swept_solid_from_shape(drilled, "drilled");
    CHECK(std::fabs(solid.sweep.X()) == Approx(10.0));
    CHECK(solid.sweep.Y() == Approx(0.0).margin(1e-9));
  }
  SECTION("a curved side other than a cylinder") {
    check_error(BRepPrimAPI_MakeCone(1, 0.5, 2).Shape(),
                "face 1 is curved (a cone): a swept solid's faces are planar, or cylinders along the sweep");
  }
  SECTION("caps that differ: a frustum") {
    const TopoDS_Shape frustum = prismatoid({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}},
                                            {{0.5, 0.5, 1}, {1.5, 0.5, 1}, {1.5, 1.5, 1}, {0.5, 1.5, 1}});
    check_error(frustum, "the caps differ: face ");
    check_error(frustum, "are parallel and opposite but not translated copies of each other (areas 4 and 1)");
  }
  SECTION("caps that differ: same area, another shape") {
    const TopoDS_Shape part = prismatoid({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}},
                                         {{-1, 0.5, 1}, {3, 0.5, 1}, {3, 1.5, 1}, {-1, 1.5, 1}});
    check_error(part, "the caps differ: face ");
    check_error(part, " is no vertex of face ");
  }
  SECTION("a side not parallel to the sweep: two grooves across each other") {
    // A box with a V-groove along Y on its +X side and one along Z on its -X side: every pair of
    // opposite faces fails, and the best (congruent caps) names the face that breaks the sweep.
    auto groove = [](const std::vector<gp_Pnt>& triangle, const gp_Vec& along) {
      BRepBuilderAPI_MakePolygon polygon;
      for (const gp_Pnt& p : triangle) polygon.Add(p);
      polygon.Close();
      return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(polygon.Wire()).Face(), along).Shape();
    };
    TopoDS_Shape part = BRepPrimAPI_MakeBox(4, 4, 4).Shape();
    part = BRepAlgoAPI_Cut(part, groove({{4.5, -1, 1.5}, {3.5, -1, 2}, {4.5, -1, 2.5}}, gp_Vec(0, 6, 0))).Shape();
    part = BRepAlgoAPI_Cut(part, groove({{-0.5, 1.5, -1}, {0.5, 2, -1}, {-0.5, 2.5, -1}}, gp_Vec(0, 0, 6))).Shape();
    check_error(part, "is not parallel to the sweep (");
    check_error(part, "a swept solid's side faces run along the sweep");
  }
  SECTION("a side split across the sweep: followed at one height over the cap's vertices, refused otherwise") {
    // Boxes fused without refining leave the sides split where the boxes meet (two faces where one
    // would do): the sweep's layers meet there (splits). Stacked, the caps are the ends of the stack.
    const TopoDS_Shape stacked =
        BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(10, 4, 1.3).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 1.3), 10, 4, 1.7).Shape())
            .Shape();
    SweptSolid s = swept_solid_from_shape(stacked, "stacked");
    CHECK(std::fabs(s.sweep.Z()) == Approx(3.0));
    REQUIRE(s.splits.size() == 1);
    CHECK(s.splits[0] == Approx(s.sweep.Z() > 0 ? 1.3 / 3 : 1.7 / 3));
    // Side by side (equal heights), the caps are the ends of the row, x = 0 and x = 14.
    const TopoDS_Shape side_by_side =
        BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(10, 4, 3).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 0), 4, 4, 3).Shape()).Shape();
    s = swept_solid_from_shape(side_by_side, "side by side");
    CHECK(std::fabs(s.sweep.X()) == Approx(14.0));
    REQUIRE(s.splits.size() == 1);
    CHECK(s.splits[0] == Approx(s.sweep.X() > 0 ? 10.0 / 14 : 4.0 / 14));
    // A plain box has none.
    CHECK(swept_solid_from_shape(BRepPrimAPI_MakeBox(10, 4, 3).Shape(), "box").splits.empty());
    // Two prisms along y whose shared face slants: the front and back are split by slanting edges.
    auto y_prism = [](const std::vector<gp_Pnt>& xz) {
      BRepBuilderAPI_MakePolygon polygon;
      for (const gp_Pnt& p : xz) polygon.Add(p);
      polygon.Close();
      return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(polygon.Wire()).Face(), gp_Vec(0, 4, 0)).Shape();
    };
    const TopoDS_Shape slanted =
        BRepAlgoAPI_Fuse(y_prism({{0, 0, 0}, {10, 0, 0}, {10, 0, 2}, {0, 0, 1}}), y_prism({{0, 0, 1}, {10, 0, 2}, {10, 0, 3}, {0, 0, 3}}))
            .Shape();
    check_error(slanted, " is split across the sweep from face ");
    check_error(slanted, " by an edge that slants (from (");
    check_error(slanted, "the sweep's layers cannot follow it; merge the split faces first (FreeCAD: Part > Create a copy > Refine shape)");
    // A box whose front is split at z = 1.3 by two edges meeting at (5, 0, 1.3): swept along x, that
    // vertex is on a line along the sweep, and the layers meet it (a split at x = 5).
    const std::vector<std::vector<int>> box_faces{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 10, 9, 8}, {8, 9, 10, 5, 4},
                                                  {1, 2, 6, 5, 10}, {2, 3, 7, 6}, {3, 0, 8, 4, 7}};
    s = swept_solid_from_shape(polyhedron({{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {0, 4, 0}, {0, 0, 3}, {10, 0, 3}, {10, 4, 3},
                                           {0, 4, 3}, {0, 0, 1.3}, {5, 0, 1.3}, {10, 0, 1.3}},
                                          box_faces),
                               "split front");
    CHECK(std::fabs(s.sweep.X()) == Approx(10.0));
    CHECK(s.splits == std::vector<double>{0.5});
    // With the cap a trapezoid (x faces not parallel), the sweep is along z: the vertex lies over no
    // vertex of the bottom cap, where the cap's mesh promises no node.
    const TopoDS_Shape off_column = polyhedron({{0, 0, 0}, {10, 0, 0}, {8, 4, 0}, {0, 4, 0}, {0, 0, 3}, {10, 0, 3}, {8, 4, 3},
                                                {0, 4, 3}, {0, 0, 1.3}, {5, 0, 1.3}, {10, 0, 1.3}},
                                               box_faces);
    check_error(off_column, " at a vertex (5, 0, 1.3) over no vertex of face ");
    check_error(off_column, "the sweep's columns of nodes cannot meet it");
  }
  SECTION("faces split where one would do, and merged a sweep: the error says to merge them") {
    // Two boxes fused into an L without refining: the caps are split too (two faces each), so no pair
    // of faces is a pair of caps; merged (ShapeUpgrade_UnifySameDomain, FreeCAD's Refine shape) the
    // solid is the L's prism.
    const TopoDS_Shape l =
        BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(10, 4, 3).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(0, 4, 0), 4, 6, 3).Shape()).Shape();
    check_error(l, "; merging its faces that could be one (11 faces into 8, as boxes fused without refining leave them "
                   "split) makes it a swept solid: merge them first (FreeCAD: Part > Create a copy > Refine shape)");
    // A boss on a box is no sweep merged either: no such hint.
    const TopoDS_Shape boss =
        BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(10, 4, 3).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(3, 1, 3), 2, 2, 2).Shape()).Shape();
    const std::string message = error_of(boss);
    INFO(message);
    CHECK_THAT(message, Contains("a swept solid's side faces run along the sweep"));
    CHECK_THAT(message, !Contains("merging its faces"));
    // Split along the sweep instead (a side drawn as two collinear lines), it is a sweep.
    BRepBuilderAPI_MakePolygon split;
    for (const gp_Pnt& p : {gp_Pnt(0, 0, 0), gp_Pnt(3.37, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 4, 0), gp_Pnt(0, 4, 0)}) split.Add(p);
    split.Close();
    const TopoDS_Shape prism = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(split.Wire()).Face(), gp_Vec(0, 0, 3)).Shape();
    CHECK_NOTHROW(swept_solid_from_shape(prism, "split"));
  }
  SECTION("no parallel faces: a tetrahedron") {
    const TopoDS_Shape tetrahedron =
        polyhedron({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 2}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
    check_error(tetrahedron, "no two faces are parallel and opposite");
  }
  SECTION("a cap the 2-D pipeline rejects: a corner sharper than 5 degrees") {
    BRepBuilderAPI_MakePolygon polygon(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(0, 0.5, 0), true);
    const TopoDS_Shape prism = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(polygon.Wire()).Face(), gp_Vec(0, 0, 1)).Shape();
    const std::string message = error_of(prism);
    INFO(message);
    CHECK_THAT(message, StartsWith("part.step (Face") && Contains(", a cap of the solid): ") && Contains("degrees"));
  }
  SECTION("nothing to sweep") { check_error(TopoDS_Shape(), "the file holds no shape"); }
}
