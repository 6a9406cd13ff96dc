#include "support/bad_shapes.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Builder.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <gp_Elips.hxx>

#include "core/geometry/occt_face.h"

namespace autoblock::test {

TopoDS_Shape raw_polygon_face(const Ring& ring, double z) {
  BRepBuilderAPI_MakePolygon polygon;
  for (const Point2& p : ring) polygon.Add(gp_Pnt(p.x, p.y, z));
  polygon.Close();
  return BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), polygon.Wire(), true).Face();
}

std::vector<BadShape> bad_shapes() {
  std::vector<BadShape> shapes;
  {
    // Circular arcs are accepted (issue 13); an ellipse is not.
    const TopoDS_Edge ellipse = BRepBuilderAPI_MakeEdge(gp_Elips(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0, 1.0)).Edge();
    const TopoDS_Wire wire = BRepBuilderAPI_MakeWire(ellipse).Wire();
    shapes.push_back({"curved-edge", BRepBuilderAPI_MakeFace(wire).Face(), "is an elliptical arc"});
  }
  // Edges at any angle are accepted (the general engine); a corner of 1.7 degrees is not.
  shapes.push_back({"sharp-corner", raw_polygon_face({{0, 0}, {100, 0}, {0, 3}}), "sharper than the smallest supported"});
  {
    const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape();
    for (TopExp_Explorer faces(cylinder, TopAbs_FACE); faces.More(); faces.Next()) {
      const TopoDS_Face face = TopoDS::Face(faces.Current());
      if (BRepAdaptor_Surface(face).GetType() == GeomAbs_Cylinder) {
        shapes.push_back({"non-planar", face, "not planar"});
        break;
      }
    }
  }
  {
    // Faces in any plane are accepted (in their own frame); this one in the XZ plane crosses itself.
    BRepBuilderAPI_MakePolygon polygon;
    for (const auto& [x, z] : std::vector<std::pair<double, double>>{{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, -1}, {0, -1}}) {
      polygon.Add(gp_Pnt(x, 0, z));
    }
    polygon.Close();
    shapes.push_back({"other-plane-crossing", BRepBuilderAPI_MakeFace(polygon.Wire(), true).Face(), "crosses itself"});
  }
  shapes.push_back({"self-crossing", raw_polygon_face({{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, -1}, {0, -1}}),
                    "crosses itself at (1, 0)"});
  shapes.push_back({"self-touching", raw_polygon_face({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}}),
                    "touches itself at (1, 1)"});
  shapes.push_back({"zero-area", raw_polygon_face({{0, 0}, {1, 0}, {1, 1e-12}, {0, 1e-12}}), "zero or tiny area"});
  {
    BRep_Builder builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    builder.Add(compound, raw_polygon_face({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    builder.Add(compound, raw_polygon_face({{2, 0}, {3, 0}, {3, 1}, {2, 1}}));
    shapes.push_back({"two-faces", compound, "holds a compound with 2 faces"});
  }
  shapes.push_back({"solid", BRepPrimAPI_MakeBox(1, 2, 3).Shape(), "holds a solid with 6 faces"});
  {
    BRepBuilderAPI_MakePolygon polygon(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0), gp_Pnt(1, 1, 0), true);
    shapes.push_back({"wire-only", polygon.Wire(), "holds a wire with no face"});
  }
  return shapes;
}

TopoDS_Shape part_with_many_faces() {
  RectilinearPolygon outline;
  outline.outer = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 8}, {0, 8}};
  outline.holes = {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
  const TopoDS_Face face = occt_face_from_polygon(outline, 0, true);
  const TopoDS_Shape slab = BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 3)).Shape();
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 0, 0), gp_Dir(0, 0, 1)), 2, 3).Shape();
  TopoDS_Compound part;
  BRep_Builder builder;
  builder.MakeCompound(part);
  builder.Add(part, slab);
  builder.Add(part, cylinder);
  return part;
}

}  // namespace autoblock::test
