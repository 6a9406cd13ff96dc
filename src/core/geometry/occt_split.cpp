#include "core/geometry/occt_split.h"

#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Bnd_Box.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include <stdexcept>

namespace autoblock {

std::vector<TopoDS_Face> split_face_along_line(const TopoDS_Face& face, CutDirection direction, double coordinate) {
  Bnd_Box box;
  BRepBndLib::Add(face, box);
  double xmin, ymin, zmin, xmax, ymax, zmax;
  box.Get(xmin, ymin, zmin, xmax, ymax, zmax);
  const double z = 0.5 * (zmin + zmax);
  const double margin = 1.0 + (xmax - xmin) + (ymax - ymin);
  const gp_Pnt a = direction == CutDirection::Vertical ? gp_Pnt(coordinate, ymin - margin, z)
                                                        : gp_Pnt(xmin - margin, coordinate, z);
  const gp_Pnt b = direction == CutDirection::Vertical ? gp_Pnt(coordinate, ymax + margin, z)
                                                        : gp_Pnt(xmax + margin, coordinate, z);
  TopTools_ListOfShape arguments, tools;
  arguments.Append(face);
  const TopoDS_Shape tool = BRepBuilderAPI_MakeEdge(a, b).Edge();
  tools.Append(tool);
  BRepAlgoAPI_Splitter splitter;
  splitter.SetArguments(arguments);
  splitter.SetTools(tools);
  splitter.Build();
  if (!splitter.IsDone()) throw std::runtime_error("OpenCASCADE could not split the face");
  std::vector<TopoDS_Face> pieces;
  for (TopExp_Explorer faces(splitter.Shape(), TopAbs_FACE); faces.More(); faces.Next()) {
    ShapeUpgrade_UnifySameDomain unify(faces.Current(), true, false, false);
    unify.Build();
    for (TopExp_Explorer merged(unify.Shape(), TopAbs_FACE); merged.More(); merged.Next()) {
      pieces.push_back(TopoDS::Face(merged.Current()));
    }
  }
  return pieces;
}

}  // namespace autoblock
