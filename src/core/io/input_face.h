// An input face in every form the pipeline needs: as the model holds it, in its own frame (see
// occt_face.h, face_frame), validated, and either on its grid (a face whose edges run along two
// perpendicular directions: the grid engine) or as a general region (edges at any angle, circular
// arcs as their chords: the general engine, core/region).
#pragma once

#include <string>

#include <TopoDS_Face.hxx>

#include "core/geometry/circular_arc.h"
#include "core/geometry/grid_face.h"
#include "core/geometry/placement.h"
#include "core/geometry/planar_face.h"
#include "core/region/region.h"

namespace autoblock {

struct InputFace {
  std::string source;  // file name or a description, for messages and reports
  TopoDS_Face model;   // the face as given
  Placement frame;     // the face's own frame in the model (identity: the model's coordinates)
  TopoDS_Face occt;    // the face in its frame: in a plane z = const (planar.z)
  PlanarFace planar;   // validated in its frame (a general face: z, normal_up and tolerance only)
  GridFace grid;       // a rectilinear face on its grid; empty for a general face
  Region region;       // a general face as a region on its lattice; empty for a rectilinear face
  FaceArcs arcs;       // a general face's circular edges, in its frame (its region holds their samples)
  // The face's vertices between two straight edges that its region or polygon leaves out (in line:
  // the canonical forms merge them, region.h, validate_polygon.h), on the region's lattice or the
  // polygon's coordinates. The mesh has a node at each, as at every other vertex of the face
  // (block_model imprints them into the blocks' sides; strip_layout draws a mesh line through each).
  std::vector<Point2> straight_vertices;
  bool is_general() const { return !region.is_empty(); }
};

// Inputs: face; what, the action for the message ("meshing", ...); instead, what the user can do
//         (empty: decompose it with the general engine's policies).
// Throws InputError when the face is general: the action needs the grid engine.
void require_rectilinear(const InputFace& face, const std::string& what, const std::string& instead = "");

// Inputs:  path (.brep, .step, .stp); face_number, which face of the file (1-based, as FreeCAD numbers
//          them; 0: the file's only face); how_to_choose, said when the choice is missing or out of
//          range (see face_selection.h).
// Outputs: the face; its source is the path, with "(FaceN)" when a number was given.
// Throws InputError (see shape_file.h and face_selection.h).
InputFace load_input_face(const std::string& path, int face_number = 0, const std::string& how_to_choose = "");

// Inputs: text, BREP text holding one face (as FreeCAD's exportBrepToString writes); source, its
// name. Output: the face in every form. Throws InputError (see shape_file.h).
InputFace input_face_from_brep_text(const std::string& text, const std::string& source);

// Inputs: face, any OpenCASCADE face (also one of a solid's).
// Output: the largest of its tolerances. Throws InputError (without the source) when a number
// OpenCASCADE would compute with is not finite or not consistent: a tolerance, the surface at its
// origin, an edge's parameter range or its curve's ends off its vertices, its curve on the face, or
// the face so far from its surface's origin that OpenCASCADE cannot compute on it precisely. Run it
// before any OpenCASCADE algorithm on a face from outside (some loop for ever on such numbers).
double check_finite_geometry(const TopoDS_Face& face);

// Inputs: face; source, its name. Output: the face in every form. Throws InputError (also when
// OpenCASCADE cannot evaluate the face's geometry).
InputFace input_face_from_occt(const TopoDS_Face& face, const std::string& source);

}  // namespace autoblock
