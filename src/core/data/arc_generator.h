// Random faces with circular arcs (issue 13), for tests, benchmarks and data sets, built with
// OpenCASCADE as a CAD system would (a boolean cut by a prism or cylinder, BRepFilletAPI_MakeFillet2d),
// in the plane z = 0.
//
// Kinds (random_arc_face draws one uniformly, each with random sizes, positions, radii and counts):
//   filleted-union    a union of 2-6 axis-aligned rectangles (shape_generator.h) with some or all of its
//                     corners filleted, convex and reflex;
//   plate-holes       a rectangular plate with one to four round holes of varied radii, anywhere in it,
//                     apart from each other and from the sides by a margin;
//   slotted-plate     a rectangular plate with a stadium slot of random length, width, position and angle;
//   rounded-polygon   a random simple polygon (general_generator.h) with some or all corners filleted;
//   rounded-plate-holes  a plate with filleted corners and one to three round holes away from them.
// A fillet's tangent length at a corner is at most 0.45 of both edges there, so two fillets never
// meet on an edge. Every face is drawn again until OpenCASCADE's checker passes it and AutoBlock's
// reader (input_face_from_occt) accepts it with its arcs (a failed fillet or cut is drawn again too).
//
// Inputs:  rng; a scale (plates are 6-24 by 4-14 times it, polygons of radius 10 times it, unions of
//          rectangles with sides 2-12 times it) or ArcOptions (scales drawn log-uniformly in
//          [min_scale, max_scale]).
// Outputs: ArcFace: the face, a name for messages, its kind, its holes (inner wires) and its circular
//          edges. Throws InputError for invalid options; std::runtime_error when a fixed-shape helper's
//          OpenCASCADE operation fails.
#pragma once

#include <random>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>

#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

struct RoundHole {
  double x = 0.0, y = 0.0, r = 1.0;
};

// A stadium: two semicircles of radius r whose centres lie length apart, the middle at centre, the
// axis at angle radians from +X.
struct Slot {
  Point2 centre;
  double length = 0.0, r = 1.0, angle = 0.0;
};

// Inputs: w, h, the plate's sides (corner at the origin); holes, inside it and apart.
// Output: the plate with the holes cut out (BRepAlgoAPI_Cut by cylinders).
TopoDS_Face plate_with_holes(double w, double h, const std::vector<RoundHole>& holes);

// Inputs: face, in the plane z = 0; holes inside it. Output: the face with the holes cut out.
TopoDS_Face cut_round_holes(const TopoDS_Face& face, const std::vector<RoundHole>& holes);

// Inputs: polygon (outer counter-clockwise, holes clockwise); radius; corners, which outer-ring
//         corners to fillet (empty: all of them).
// Output: the face with those corners filleted (BRepFilletAPI_MakeFillet2d): tangent arcs.
TopoDS_Face filleted_polygon(const RectilinearPolygon& polygon, double radius, const std::vector<int>& corners = {});

// Inputs: polygon; radii, one per outer-ring corner (0: left sharp). Output: as above, each corner with
//         its own radius.
TopoDS_Face filleted_polygon(const RectilinearPolygon& polygon, const std::vector<double>& radii);

// Inputs: w, h, the plate; slot inside it. Output: the plate with the slot cut out.
TopoDS_Face slotted_plate(double w, double h, const Slot& slot);

// A 20 x 10 plate with a stadium-shaped slot (two semicircles of radius 2, centres 8 apart).
TopoDS_Face slotted_plate();

// A disk of radius r centred at (x, y).
TopoDS_Face disk(double x, double y, double r);

enum class ArcKind { FilletedUnion, PlateHoles, SlottedPlate, RoundedPolygon, RoundedPlateHoles };
constexpr int kArcKinds = 5;

// "filleted-union", "plate-holes", "slotted-plate", "rounded-polygon", "rounded-plate-holes".
std::string arc_kind_name(ArcKind kind);

struct ArcFace {
  TopoDS_Face face;
  std::string name;  // for messages: "plate with 3 holes", ...
  ArcKind kind = ArcKind::PlateHoles;
  int holes = 0;     // inner wires
  int arcs = 0;      // circular edges
};

struct ArcOptions {
  double min_scale = 0.1;  // each face's scale log-uniform in [min_scale, max_scale]
  double max_scale = 100.0;
};

// A face of a random kind at the given scale.
ArcFace random_arc_face(std::mt19937_64& rng, double scale = 1.0);

// A face of the given kind at the given scale.
ArcFace random_arc_face(std::mt19937_64& rng, ArcKind kind, double scale);

// A face of a random kind at a random scale (0 < min_scale <= max_scale, else InputError).
ArcFace generate_arc_face(std::mt19937_64& rng, const ArcOptions& options);

}  // namespace autoblock
