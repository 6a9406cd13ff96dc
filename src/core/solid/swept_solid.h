// A solid that is a straight sweep of a planar face: two congruent planar caps (one a translated
// copy of the other) joined by side faces, planar or cylinders (extruded arcs, drilled holes; a
// B-spline surface that is a cylinder, edge_curve.h face_cylinder, too), that
// all run along one direction, the sweep vector (normal to the caps or oblique). Detected from any shape read from a file; anything else
// is an InputError that says why, naming the face (numbered as FreeCAD numbers them: face k is
// Face k of `autoblock faces`).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <GProp_GProps.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "core/io/input_face.h"

namespace autoblock {

// The relative precision of the areas, volume and centroids of a solid with B-spline or Bezier
// geometry (BRepGProp's adaptive integration): its fixed rule, exact and fast on planes, cylinders,
// lines and circles, is 0.02 % off on a face bounded by B-spline circles (CATIA's holes), enough for
// two caps to differ and a drilled plate not to be a sweep.
constexpr double kPropertiesPrecision = 1e-9;

// Inputs: shape; splines, whether its geometry has B-spline or Bezier surfaces or curves
// (SweptSolid::splines). Output: its surface area (volume) properties, by the fixed rule or, with
// splines, to kPropertiesPrecision.
void surface_properties(const TopoDS_Shape& shape, bool splines, GProp_GProps& properties);
void volume_properties(const TopoDS_Shape& shape, bool splines, GProp_GProps& properties);

// An edge of a side face seen at one height: points along it moved to the bottom cap's plane (model
// coordinates; the bottom cap's own edges are such edges as they are), and the side face (its number).
struct SideEdge {
  std::vector<std::array<double, 3>> points;
  int face = 0;
};

// Inputs: edge. Output: points along it: its ends when it is a line, else kEdgeSamples + 1 points evenly
// in its parameter.
constexpr int kEdgeSamples = 96;
std::vector<gp_Pnt> edge_samples(const TopoDS_Edge& edge);

struct SweptSolid {
  std::string source;              // file name or description, for messages and reports
  TopoDS_Solid solid;              // model coordinates, oriented (its faces' normals point outwards)
  std::vector<TopoDS_Face> faces;  // faces[k - 1] is face k (FreeCAD's numbering of the shape read)
  int bottom = 0, top = 0;         // the caps' face numbers: the sweep runs from bottom to top
  gp_Vec sweep;                    // top = bottom translated by sweep (model coordinates)
  // The heights, as fractions of the sweep in (0, 1), increasing, where side faces are split across
  // the sweep (boxes stacked and fused without refining): the layers meet there. Empty in a plain sweep.
  std::vector<double> splits;
  double volume = 0.0, area = 0.0; // the solid's volume and surface area (OpenCASCADE's GProp)
  bool splines = false;            // a surface or curve of it is a B-spline or Bezier one
  InputFace cap;                   // the bottom cap, checked as the 2-D pipeline checks a face
};

// Inputs:  shape, as read from a file (a solid, a compound holding one solid, or a closed shell);
//          source, its name for messages.
// Outputs: the solid, its caps and sweep vector. When several face pairs qualify (a box), the caps
//          with the most vertices, then the largest area, then the lowest face numbers.
// Throws InputError "<source>: <why>", one line, for: no solid or shell; more than one solid; an open
// shell (a face with a free edge); a solid with more than one shell (a cavity); a curved face other
// than a cylinder; a cylinder whose axis is not along the sweep; no two
// parallel opposite faces; caps that are not translated copies of each other; a face not parallel to
// the sweep; a side face split across the sweep where the layers cannot follow it (an edge between the
// caps, not straight along the sweep, that slants, or with a vertex over no vertex of the bottom cap;
// a split at one height over the cap's vertices, as boxes fused without refining leave, is in splits,
// and such a solid must pass OpenCASCADE's checker before its sides are cut between the splits);
// a cap the 2-D pipeline rejects (its message, the cap named).
SweptSolid swept_solid_from_shape(const TopoDS_Shape& shape, const std::string& source);

// Inputs: solid, with splits (swept_solid_from_shape has checked it: OpenCASCADE's checker passes it).
// Output: per stretch between the splits (or a cap), the side faces' edges at its middle height (the side
// faces cut there by a plane along the cap: one OpenCASCADE section for all), moved to the bottom cap's
// plane: which face a side quad of that stretch lies on.
std::vector<std::vector<SideEdge>> side_edges_by_stretch(const SweptSolid& solid);

// Inputs: shape. Output: true when it should be meshed as a solid rather than as one face: it holds
// exactly one solid, or no solid and a shell of more than one face.
bool holds_one_solid(const TopoDS_Shape& shape);

}  // namespace autoblock
