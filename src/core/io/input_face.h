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

// Inputs: path (.brep, .step, .stp). Output: the file's face. Throws InputError (see shape_file.h).
InputFace load_input_face(const std::string& path);

// Inputs: text, BREP text holding one face (as FreeCAD's exportBrepToString writes); source, its
// name. Output: the face in every form. Throws InputError (see shape_file.h).
InputFace input_face_from_brep_text(const std::string& text, const std::string& source);

// Inputs: face; source, its name. Output: the face in every form. Throws InputError (also when
// OpenCASCADE cannot evaluate the face's geometry).
InputFace input_face_from_occt(const TopoDS_Face& face, const std::string& source);

}  // namespace autoblock
