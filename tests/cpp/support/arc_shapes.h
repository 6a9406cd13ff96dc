// Faces with circular arcs for the tests (issue 13): plates with round holes, filleted polygons, a
// slotted plate, a disk, and a seeded generator of such faces. Built with OpenCASCADE as a CAD
// system would (a boolean cut by cylinders, BRepFilletAPI_MakeFillet2d), in the plane z = 0.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>

#include "core/geometry/rectilinear_polygon.h"

namespace autoblock::test {

struct RoundHole {
  double x = 0.0, y = 0.0, r = 1.0;
};

// Inputs: w, h, the plate's sides (corner at the origin); holes, inside it and apart.
// Output: the plate with the holes cut out (BRepAlgoAPI_Cut by cylinders).
TopoDS_Face plate_with_holes(double w, double h, const std::vector<RoundHole>& holes);

// Inputs: polygon (outer counter-clockwise, holes clockwise); radius; corners, which outer-ring
//         corners to fillet (empty: all of them).
// Output: the face with those corners filleted (BRepFilletAPI_MakeFillet2d): tangent arcs.
TopoDS_Face filleted_polygon(const RectilinearPolygon& polygon, double radius, const std::vector<int>& corners = {});

// A 20 x 10 plate with a stadium-shaped slot (two semicircles of radius 2, centres 8 apart).
TopoDS_Face slotted_plate();

// A disk of radius r centred at (x, y).
TopoDS_Face disk(double x, double y, double r);

// A seeded face with arcs: a plate with one to four holes, a filleted rectangle or L (some or all
// corners, convex and reflex), a filleted plate with holes, or a slotted plate; at the given scale.
// Output: the face and a name for messages.
struct ArcFace {
  TopoDS_Face face;
  std::string name;
};
ArcFace random_arc_face(std::mt19937_64& rng, double scale = 1.0);

}  // namespace autoblock::test
