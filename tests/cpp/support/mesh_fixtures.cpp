#include "support/mesh_fixtures.h"

#include <catch2/catch.hpp>

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include <cmath>

#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/mesh/mapped_mesh.h"
#include "core/region/block.h"
#include "support/test_shapes.h"

namespace autoblock::test {
namespace {

bool on_polygon_boundary(const gp_Pnt& p, const RectilinearPolygon& polygon) {
  auto on_ring = [&](const Ring& ring) {
    for (size_t k = 0; k < ring.size(); ++k) {
      const Point2& a = ring[k];
      const Point2& b = ring[(k + 1) % ring.size()];
      const double eps = 1e-9;
      if (p.X() >= std::min(a.x, b.x) - eps && p.X() <= std::max(a.x, b.x) + eps && p.Y() >= std::min(a.y, b.y) - eps &&
          p.Y() <= std::max(a.y, b.y) + eps) {
        return true;
      }
    }
    return false;
  };
  if (on_ring(polygon.outer)) return true;
  for (const Ring& hole : polygon.holes) {
    if (on_ring(hole)) return true;
  }
  return false;
}

}  // namespace

HandModel hand_model(const Ring& outer, const std::vector<Ring>& holes, const std::vector<Box>& blocks) {
  HandModel m;
  m.face = input_face_from_occt(occt_face_from_polygon(polygon_of(outer, holes), 0.0, true), "hand-made");
  m.blocks = blocks;
  std::vector<TopoDS_Face> faces;
  for (const Box& b : blocks) faces.push_back(occt_rectangle(b, 0.0, true));
  m.model = conformal_merge(faces);
  m.layout = strip_layout(m.face.grid, blocks);
  return m;
}

QuadMesh hand_mesh(const HandModel& m, const IntervalAssignment& intervals) {
  return mapped_mesh(m.model, m.blocks, m.face.grid, m.layout, intervals, 0.0);
}

std::vector<Box> pinwheel_blocks() {
  return {Box{0, 0, 2, 1}, Box{2, 0, 3, 2}, Box{1, 2, 3, 3}, Box{0, 1, 1, 3}, Box{1, 1, 2, 2}};
}

void check_conformal_model(const ConformalBlocks& model, const RectilinearPolygon& polygon) {
  CHECK(occt_shape_valid(model.compound));
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(model.compound, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int e = 1; e <= edge_faces.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(edge_faces.FindKey(e));
    const gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge)), b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
    const gp_Pnt middle((a.X() + b.X()) / 2, (a.Y() + b.Y()) / 2, a.Z());
    const int faces = edge_faces(e).Extent();
    INFO("edge (" << a.X() << ", " << a.Y() << ")-(" << b.X() << ", " << b.Y() << ") in " << faces << " faces");
    CHECK((faces == 1 || faces == 2));
    CHECK(on_polygon_boundary(middle, polygon) == (faces == 1));  // inside: shared (IsSame) by two faces
  }
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(model.compound, TopAbs_VERTEX, vertices);
  double area = 0;
  for (const TopoDS_Face& face : model.faces) {
    area += occt_area(face);
    Bnd_Box box;
    BRepBndLib::Add(face, box);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    const double eps = 1e-6;
    TopTools_IndexedMapOfShape own;
    TopExp::MapShapes(face, TopAbs_VERTEX, own);
    for (int v = 1; v <= vertices.Extent(); ++v) {
      const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
      const bool inside_box = p.X() > x0 - eps && p.X() < x1 + eps && p.Y() > y0 - eps && p.Y() < y1 + eps;
      const bool on_side = inside_box && (std::fabs(p.X() - x0) < eps || std::fabs(p.X() - x1) < eps ||
                                          std::fabs(p.Y() - y0) < eps || std::fabs(p.Y() - y1) < eps);
      if (on_side) {
        INFO("vertex (" << p.X() << ", " << p.Y() << ") lies on a face's side");
        CHECK(own.Contains(vertices(v)));  // T-junctions imprinted
      }
    }
  }
  CHECK(area == Approx(polygon_area(polygon)).epsilon(1e-12));
}

FinishedRegion finished_block(int id, const Ring& ring, double quantum) {
  FinishedRegion f;
  f.id = id;
  f.region = Region(ring, {}, quantum);
  const auto corners = block_corners(f.region);
  REQUIRE(corners);
  f.corners = *corners;
  return f;
}

}  // namespace autoblock::test
