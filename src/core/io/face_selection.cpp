#include "core/io/face_selection.h"

#include "core/io/input_face.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Dir.hxx>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/geometry/grid_face.h"
#include "core/geometry/occt_face.h"

namespace autoblock {
namespace {

std::string shape_type_name(TopAbs_ShapeEnum type) {
  switch (type) {
    case TopAbs_COMPOUND: return "compound";
    case TopAbs_COMPSOLID: return "composite solid";
    case TopAbs_SOLID: return "solid";
    case TopAbs_SHELL: return "shell";
    case TopAbs_FACE: return "face";
    case TopAbs_WIRE: return "wire";
    case TopAbs_EDGE: return "edge";
    case TopAbs_VERTEX: return "vertex";
    default: return "shape";
  }
}

TopTools_IndexedMapOfShape face_map(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  if (!shape.IsNull()) TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return faces;
}

}  // namespace

std::vector<FaceSummary> list_faces(const TopoDS_Shape& shape) {
  const TopTools_IndexedMapOfShape faces = face_map(shape);
  std::vector<FaceSummary> list;
  for (int k = 1; k <= faces.Extent(); ++k) {
    const TopoDS_Face face = TopoDS::Face(faces(k));
    FaceSummary summary;
    summary.number = k;
    summary.surface = surface_name(face);
    GProp_GProps properties;
    BRepGProp::SurfaceProperties(face, properties);
    summary.area = properties.Mass();
    gp_Dir normal;
    summary.planar = planar_face_normal(face, &normal);
    if (summary.planar) {
      summary.normal[0] = normal.X();
      summary.normal[1] = normal.Y();
      summary.normal[2] = normal.Z();
    }
    try {
      input_face_from_occt(face, "");  // the same checks as every command's
    } catch (const InputError& e) {
      const std::string message = e.what();
      summary.problem = message.rfind(": ", 0) == 0 ? message.substr(2) : message;
    }
    list.push_back(summary);
  }
  return list;
}

TopoDS_Face select_face(const TopoDS_Shape& shape, const std::string& what, int number,
                        const std::string& how_to_choose) {
  if (shape.IsNull()) throw InputError(what + " holds no shape");
  const TopTools_IndexedMapOfShape faces = face_map(shape);
  const int count = faces.Extent();
  const std::string holds = what + " holds " + with_article(shape_type_name(shape.ShapeType())) + " with ";
  const std::string hint = how_to_choose.empty() ? "" : "; " + how_to_choose;
  if (count == 0) throw InputError(holds + "no face; expected a planar face");
  if (number == 0) {
    if (count == 1) return TopoDS::Face(faces(1));
    throw InputError(holds + counted(count, "face") + "; " +
                     (how_to_choose.empty() ? "expected exactly one planar face" : how_to_choose));
  }
  if (number < 1 || number > count) {
    const std::string held = shape.ShapeType() == TopAbs_FACE
                                 ? "it is a single face (face 1)"
                                 : "it holds " + with_article(shape_type_name(shape.ShapeType())) + " with " +
                                       counted(count, "face") +
                                       (count == 1 ? " (face 1)" : " (faces 1 to " + std::to_string(count) + ")");
    throw InputError(what + " has no face " + std::to_string(number) + ": " + held + hint);
  }
  return TopoDS::Face(faces(number));
}

std::string face_source_name(const std::string& source, int number) {
  return number == 0 ? source : source + " (Face" + std::to_string(number) + ")";
}

}  // namespace autoblock
