// Choosing the face to work on from a shape read from a file (a part's solid, a shell, a compound
// or a single face): by its number, 1-based in the order FreeCAD numbers faces (Face1, Face2, ...:
// TopExp::MapShapes order), or the only face when there is one; and a listing of the faces to choose
// from.
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace autoblock {

struct FaceSummary {
  int number = 0;             // 1-based (FreeCAD's FaceN)
  std::string surface;        // "plane", "cylinder", "B-spline surface", ...
  bool planar = false;        // a plane, or within 1e-7 of one
  double area = 0.0;
  double normal[3] = {0, 0, 0};  // planar faces: the normal, the face's orientation applied
  std::string problem;        // empty when AutoBlock accepts the face; else why not (the check's message)
};

// Inputs:  shape, as read from a file.
// Outputs: every face of the shape, numbered as FreeCAD numbers them, each checked as AutoBlock
//          would check it.
std::vector<FaceSummary> list_faces(const TopoDS_Shape& shape);

// Inputs:  shape; what, where it came from for messages ("part.step: the file"); number, the face to
//          take (1-based) or 0 for "the only face"; how_to_choose, appended to the message when the
//          choice is missing or out of range (e.g. "choose one with --face N").
// Outputs: the face. Throws InputError naming what was found ("a solid with 12 faces", "a compound
//          with no face") when number is 0 and the shape does not hold exactly one face, or when
//          number is not between 1 and the number of faces.
TopoDS_Face select_face(const TopoDS_Shape& shape, const std::string& what, int number,
                        const std::string& how_to_choose = "");

// Inputs: source (a file name), number (0: the only face). Output: the name of the face for messages
// and reports: "part.step" or "part.step (Face3)".
std::string face_source_name(const std::string& source, int number);

}  // namespace autoblock
