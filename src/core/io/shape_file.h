// Reading faces from and writing shapes to .brep and .step/.stp files (and BREP text).
//
// Hostile input: OpenCASCADE's readers can loop for ever or crash on a malformed file (a number cut
// short, a count that does not match). So a read runs
//   1. in a child process (fork) with a time budget (AUTOBLOCK_READ_TIMEOUT seconds, default 30;
//      0 reads in this process), a memory limit and OpenCASCADE's signal handling: a crash or an
//      overrun there kills only the child (which also dies with its parent), and becomes an
//      InputError here;
//   2. from a stream that fails loudly: a malformed number or count, or reading past the end,
//      throws instead of leaving OpenCASCADE spinning on a failed stream.
// The child sends the shape back as BREP text that OpenCASCADE itself wrote; this process reads
// that (step 2 only). An optional check (e.g. the face validation) runs in the child too, so a
// crash inside it is contained as well; the caller repeats it on the shape it gets back.
#pragma once

#include <functional>
#include <string>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>


namespace autoblock {

// Inputs:  a shape just read; throws (InputError) when it is not acceptable.
using ShapeCheck = std::function<void(const TopoDS_Shape&)>;

// Inputs:  path to a .brep, .step or .stp file; check, run on the shape in the reading process.
// Outputs: the shape it holds.
// Throws InputError for a missing, unreadable, empty, garbage or malformed file (also when the
// reader crashes or overruns its time budget), or an unknown extension; check's errors pass through.
TopoDS_Shape read_shape_file(const std::string& path, const ShapeCheck& check = {});

// Inputs:  text, BREP text (as FreeCAD's exportBrepToString writes); check as above.
// Output: the shape. Throws InputError when the text is empty, not BREP or malformed.
TopoDS_Shape read_brep_text(const std::string& text, const ShapeCheck& check = {});

// Choosing a face of a shape: io/face_selection.h (select_face).

// Inputs: path (.brep, .step or .stp), shape. Writes atomically (atomic_file.h): a failure or a
// kill never leaves a half-written file. Throws InputError when the extension is unknown or the
// file cannot be written.
void write_shape_file(const std::string& path, const TopoDS_Shape& shape);

// Inputs: shape. Output: its BREP text.
std::string write_brep_text(const TopoDS_Shape& shape);

}  // namespace autoblock
