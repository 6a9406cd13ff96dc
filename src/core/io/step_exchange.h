// STEP files through OpenCASCADE's STEP translator, in libautoblock_step.so: the translator's
// libraries (TKXSBase, TKSTEP*) take about a third of the core's start-up, so the core loads them on
// first use (shape_file.h), and a command on a BREP file never pays for them.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>

namespace autoblock {

// Inputs:  path, a STEP file.
// Outputs: the file's shape (its roots as one shape). Throws InputError naming the file when it is
//          not a readable STEP file or holds no shape.
TopoDS_Shape read_step_file(const std::string& path);

// Inputs:  shape; path, the file to write (the caller writes it atomically).
// Outputs: true when the translator wrote it.
bool write_step_file(const TopoDS_Shape& shape, const std::string& path);

}  // namespace autoblock
