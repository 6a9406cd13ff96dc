// OpenCASCADE faces to and from PlanarFace.
#pragma once

#include <TopoDS_Face.hxx>
#include <gp_Dir.hxx>

#include <string>

#include "core/geometry/planar_face.h"

namespace autoblock {

// Inputs:  face, any TopoDS_Face.
// Outputs: the face as a validated PlanarFace (see validate_polygon.h for the polygon checks).
// Throws InputError when the face is not planar, does not lie parallel to the XY plane, has a
// curved edge or an open wire (naming the wire, the edge and its end points), or fails any check
// of validate_rings.
PlanarFace planar_face_from_occt(const TopoDS_Face& face);

// Inputs: face. Output: the name of its surface's type: "plane", "cylinder", "B-spline surface", ...
std::string surface_name(const TopoDS_Face& face);

// Inputs:  face.
// Outputs: true and *normal, the face's normal (its orientation applied), when the face is planar (its
//          surface is a plane or within 1e-7 of one); false otherwise.
bool planar_face_normal(const TopoDS_Face& face, gp_Dir* normal);

// Inputs:  polygon (outer counter-clockwise, holes clockwise), z, normal_up.
// Outputs: the face in the plane z = const with that polygon as boundary, normal +Z (or -Z).
TopoDS_Face occt_face_from_polygon(const RectilinearPolygon& polygon, double z, bool normal_up);

// Inputs:  box, z, normal_up. Output: the rectangular face (same conventions as above).
TopoDS_Face occt_rectangle(const Box& box, double z, bool normal_up);

}  // namespace autoblock
