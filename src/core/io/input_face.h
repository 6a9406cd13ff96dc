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

// Inputs: face; source, its name. Output: the face in every form. Throws InputError.
InputFace input_face_from_occt(const TopoDS_Face& face, const std::string& source);

}  // namespace autoblock
