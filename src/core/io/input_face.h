// An input face in every form the pipeline needs: as OpenCASCADE holds it, validated, and on its
// grid.
#pragma once

#include <string>

#include <TopoDS_Face.hxx>

#include "core/geometry/grid_face.h"
#include "core/geometry/planar_face.h"

namespace autoblock {

struct InputFace {
  std::string source;  // file name or a description, for messages and reports
  TopoDS_Face occt;
  PlanarFace planar;
  GridFace grid;
};

// Inputs:  path (.brep, .step, .stp); face_number, which face of the file (1-based, as FreeCAD numbers
//          them; 0: the file's only face); how_to_choose, said when the choice is missing or out of
//          range (see face_selection.h).
// Outputs: the face; its source is the path, with "(FaceN)" when a number was given.
// Throws InputError (see shape_file.h and face_selection.h).
InputFace load_input_face(const std::string& path, int face_number = 0, const std::string& how_to_choose = "");

// Inputs: text, BREP text holding one face (as FreeCAD's exportBrepToString writes); source, its
// name. Output: the face in every form. Throws InputError (see shape_file.h).
InputFace input_face_from_brep_text(const std::string& text, const std::string& source);

// Inputs: face; source, its name. Output: the face in every form. Throws InputError (also when
// OpenCASCADE cannot evaluate the face's geometry).
InputFace input_face_from_occt(const TopoDS_Face& face, const std::string& source);

}  // namespace autoblock
