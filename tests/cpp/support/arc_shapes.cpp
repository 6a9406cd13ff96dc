#include "support/arc_shapes.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Tool.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepFilletAPI_MakeFillet2d.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry/occt_face.h"

namespace autoblock::test {
namespace {

TopoDS_Face first_face(const TopoDS_Shape& shape) {
  TopExp_Explorer faces(shape, TopAbs_FACE);
  if (!faces.More()) throw std::runtime_error("arc_shapes: no face");
  return TopoDS::Face(faces.Current());
}

// The face less the solid (a prism through z = 0).
TopoDS_Face cut(const TopoDS_Face& face, const TopoDS_Shape& tool) {
  BRepAlgoAPI_Cut op(face, tool);
  if (!op.IsDone()) throw std::runtime_error("arc_shapes: the cut failed");
  return first_face(op.Shape());
}

TopoDS_Shape cylinder(double x, double y, double r) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp_Dir(0, 0, 1)), r, 2).Shape();
}

double uniform(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

}  // namespace

TopoDS_Face plate_with_holes(double w, double h, const std::vector<RoundHole>& holes) {
  TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0, w, 0, h).Face();
  for (const RoundHole& hole : holes) face = cut(face, cylinder(hole.x, hole.y, hole.r));
  return face;
}

TopoDS_Face filleted_polygon(const RectilinearPolygon& polygon, double radius, const std::vector<int>& corners) {
  const TopoDS_Face face = occt_face_from_polygon(polygon, 0.0, true);
  BRepFilletAPI_MakeFillet2d fillet(face);
  // The outer ring's corners by position (the face's vertices include the holes').
  for (size_t k = 0; k < polygon.outer.size(); ++k) {
    if (!corners.empty() && std::find(corners.begin(), corners.end(), static_cast<int>(k)) == corners.end()) continue;
    const Point2 p = polygon.outer[k];
    TopTools_IndexedMapOfShape vertices;
    TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
    for (int v = 1; v <= vertices.Extent(); ++v) {
      const gp_Pnt at = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
      if (std::hypot(at.X() - p.x, at.Y() - p.y) < 1e-9) fillet.AddFillet(TopoDS::Vertex(vertices(v)), radius);
    }
  }
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("arc_shapes: the fillet failed");
  return first_face(fillet.Shape());
}

TopoDS_Face slotted_plate() {
  const gp_Pnt a(6, 3, 0), b(14, 3, 0), c(14, 7, 0), d(6, 7, 0);
  const TopoDS_Edge bottom = BRepBuilderAPI_MakeEdge(a, b).Edge();
  const TopoDS_Edge right = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(b, gp_Pnt(16, 5, 0), c).Value()).Edge();
  const TopoDS_Edge top = BRepBuilderAPI_MakeEdge(c, d).Edge();
  const TopoDS_Edge left = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(d, gp_Pnt(4, 5, 0), a).Value()).Edge();
  const TopoDS_Wire wire = BRepBuilderAPI_MakeWire(bottom, right, top, left).Wire();
  const TopoDS_Face slot = BRepBuilderAPI_MakeFace(wire).Face();
  const TopoDS_Shape tool = BRepPrimAPI_MakePrism(slot, gp_Vec(0, 0, 2)).Shape();
  gp_Trsf down;
  down.SetTranslation(gp_Vec(0, 0, -1));
  const TopoDS_Face plate = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0, 20, 0, 10).Face();
  return cut(plate, tool.Moved(TopLoc_Location(down)));
}

TopoDS_Face disk(double x, double y, double r) {
  const TopoDS_Edge circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(x, y, 0), gp_Dir(0, 0, 1)), r)).Edge();
  return BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(circle).Wire()).Face();
}

ArcFace random_arc_face(std::mt19937_64& rng, double scale) {
  const int kind = std::uniform_int_distribution<int>(0, 4)(rng);
  const double w = scale * uniform(rng, 8, 20), h = scale * uniform(rng, 5, 12);
  // Holes on a coarse grid of cells, one per cell at most, each well inside its cell.
  auto holes = [&](int count, double margin) {
    std::vector<RoundHole> out;
    const int columns = std::max(1, static_cast<int>(w / (scale * 5))), rows = std::max(1, static_cast<int>(h / (scale * 5)));
    std::vector<int> cells(static_cast<size_t>(columns * rows));
    for (size_t k = 0; k < cells.size(); ++k) cells[k] = static_cast<int>(k);
    std::shuffle(cells.begin(), cells.end(), rng);
    for (int k = 0; k < std::min<int>(count, static_cast<int>(cells.size())); ++k) {
      const double cw = w / columns, ch = h / rows;
      const int i = cells[static_cast<size_t>(k)] % columns, j = cells[static_cast<size_t>(k)] / columns;
      const double room = 0.5 * std::min(cw, ch) - margin;
      const double r = uniform(rng, 0.25, 0.6) * room;
      const double x = (i + 0.5) * cw + uniform(rng, -1, 1) * (room - r) * 0.5;
      const double y = (j + 0.5) * ch + uniform(rng, -1, 1) * (room - r) * 0.5;
      out.push_back({x, y, r});
    }
    return out;
  };
  const Ring rectangle{{0, 0}, {w, 0}, {w, h}, {0, h}};
  switch (kind) {
    case 0: {
      const int n = std::uniform_int_distribution<int>(1, 4)(rng);
      return {plate_with_holes(w, h, holes(n, 0.1 * scale)), "plate with " + std::to_string(n) + " holes"};
    }
    case 1: {
      const double r = uniform(rng, 0.1, 0.45) * std::min(w, h);
      std::vector<int> corners;
      for (int k = 0; k < 4; ++k) {
        if (std::uniform_int_distribution<int>(0, 2)(rng)) corners.push_back(k);
      }
      if (corners.empty()) corners.push_back(0);
      return {filleted_polygon(RectilinearPolygon{rectangle, {}}, r, corners), "filleted rectangle"};
    }
    case 2: {
      const double a = uniform(rng, 0.3, 0.6) * w, b = uniform(rng, 0.3, 0.6) * h;
      const Ring l{{0, 0}, {w, 0}, {w, b}, {a, b}, {a, h}, {0, h}};
      const double r = uniform(rng, 0.1, 0.4) * std::min({a, b, w - a, h - b});
      return {filleted_polygon(RectilinearPolygon{l, {}}, r), "filleted L"};
    }
    case 3: {
      // Fillets on the plate's corners, holes away from them.
      const double r = uniform(rng, 0.1, 0.2) * std::min(w, h);
      const TopoDS_Face rounded = filleted_polygon(RectilinearPolygon{rectangle, {}}, r);
      TopoDS_Face face = rounded;
      for (const RoundHole& hole : holes(std::uniform_int_distribution<int>(1, 3)(rng), r + 0.1 * scale)) {
        face = cut(face, cylinder(hole.x, hole.y, hole.r));
      }
      return {face, "rounded plate with holes"};
    }
    default: {
      gp_Trsf s;
      s.SetScale(gp_Pnt(0, 0, 0), scale);
      return {TopoDS::Face(BRepBuilderAPI_Transform(slotted_plate(), s, true).Shape()), "slotted plate"};
    }
  }
}

}  // namespace autoblock::test
