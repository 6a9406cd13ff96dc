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
#include <Standard_Failure.hxx>
#include <string>

#include <stdexcept>

namespace autoblock {
namespace {

// The face split by the tools (edges), each piece's collinear edges merged.
std::vector<TopoDS_Face> split_face(const TopoDS_Face& face, const TopTools_ListOfShape& tools, double fuzzy) {
  TopTools_ListOfShape arguments;
  arguments.Append(face);
  BRepAlgoAPI_Splitter splitter;
  splitter.SetArguments(arguments);
  splitter.SetTools(tools);
  splitter.SetRunParallel(false);
  if (fuzzy > 0) splitter.SetFuzzyValue(fuzzy);
  try {
    splitter.Build();
  } catch (const Standard_Failure& e) {
    throw std::runtime_error(std::string("OpenCASCADE could not split the face: ") + e.GetMessageString());
  }
  if (!splitter.IsDone() || splitter.HasErrors()) throw std::runtime_error("OpenCASCADE could not split the face");
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

}  // namespace

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
  TopTools_ListOfShape tools;
  tools.Append(BRepBuilderAPI_MakeEdge(a, b).Edge());
  return split_face(face, tools, 0.0);
}

std::vector<TopoDS_Face> split_face_along_segments(const TopoDS_Face& face,
                                                   const std::vector<std::pair<Point2, Point2>>& segments,
                                                   double fuzzy) {
  Bnd_Box box;
  BRepBndLib::Add(face, box);
  double xmin, ymin, zmin, xmax, ymax, zmax;
  box.Get(xmin, ymin, zmin, xmax, ymax, zmax);
  const double z = 0.5 * (zmin + zmax);
  TopTools_ListOfShape tools;
  for (const auto& [a, b] : segments) {
    BRepBuilderAPI_MakeEdge edge(gp_Pnt(a.x, a.y, z), gp_Pnt(b.x, b.y, z));
    if (!edge.IsDone()) throw std::runtime_error("OpenCASCADE could not make a cut segment");
    tools.Append(edge.Edge());
  }
  return split_face(face, tools, fuzzy);
}

}  // namespace autoblock
