// Shapes that AutoBlock must reject, each with the words its error message must contain.
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "core/geometry/rectilinear_polygon.h"

namespace autoblock::test {

struct BadShape {
  std::string name;      // short name, usable as a file stem
  TopoDS_Shape shape;
  std::string expected;  // part of the error message
};

// Inputs: ring (any orientation), z. Output: the planar face bounded by it (not validated).
TopoDS_Shape raw_polygon_face(const Ring& ring, double z = 0.0);

// One shape per class of bad geometry: curved edge, non-axis edge, non-planar face, face in another
// plane, crossing boundary, touching boundary, zero area, two faces, a solid, no face.
std::vector<BadShape> bad_shapes();

// A part for choosing faces (--face N): a compound of two solids, an L-shaped slab with a square hole
// (outer (0,0) (10,0) (10,4) (4,4) (4,8) (0,8), hole [1,3]^2, z from 0 to 3: its top and bottom faces,
// of area 52, and its sides, each in its own frame) and a cylinder beside it (radius 2 at (20, 0): its
// disks are taken too, its side is curved).
TopoDS_Shape part_with_many_faces();

}  // namespace autoblock::test
