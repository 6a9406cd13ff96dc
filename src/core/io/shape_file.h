// Reading faces from and writing shapes to .brep and .step/.stp files (and BREP text).
#pragma once

#include <string>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>


namespace autoblock {

// Inputs:  path to a .brep, .step or .stp file.
// Outputs: the shape it holds.
// Throws InputError for a missing, unreadable, empty or garbage file, or an unknown extension.
TopoDS_Shape read_shape_file(const std::string& path);

// Inputs:  text, BREP text (as FreeCAD's exportBrepToString writes). Output: the shape.
// Throws InputError when the text is empty or not BREP.
TopoDS_Shape read_brep_text(const std::string& text);

// Inputs:  shape, what (a description of where it came from, for messages).
// Outputs: its single face. Throws InputError naming what was found (a solid with 6 faces, a
//          compound of 3 faces, no face at all, ...) unless the shape holds exactly one face.
TopoDS_Face single_face(const TopoDS_Shape& shape, const std::string& what);

// Inputs: path (.brep, .step or .stp), shape. Writes atomically: a temporary file renamed into
// place, so a failure never leaves a half-written file. Throws InputError when the extension is
// unknown or the file cannot be written.
void write_shape_file(const std::string& path, const TopoDS_Shape& shape);

// Inputs: shape. Output: its BREP text.
std::string write_brep_text(const TopoDS_Shape& shape);

}  // namespace autoblock
