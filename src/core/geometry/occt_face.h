// OpenCASCADE faces to and from PlanarFace.
#pragma once

#include <TopoDS_Face.hxx>

#include "core/geometry/planar_face.h"

namespace autoblock {

// Inputs:  face, any TopoDS_Face.
// Outputs: the face as a validated PlanarFace (see validate_polygon.h for the polygon checks).
// Throws InputError when the face is not planar, does not lie parallel to the XY plane, has a
// curved edge or an open wire (naming the wire, the edge and its end points), or fails any check
// of validate_rings.
PlanarFace planar_face_from_occt(const TopoDS_Face& face);

// Inputs:  polygon (outer counter-clockwise, holes clockwise), z, normal_up.
// Outputs: the face in the plane z = const with that polygon as boundary, normal +Z (or -Z).
TopoDS_Face occt_face_from_polygon(const RectilinearPolygon& polygon, double z, bool normal_up);

// Inputs:  box, z, normal_up. Output: the rectangular face (same conventions as above).
TopoDS_Face occt_rectangle(const Box& box, double z, bool normal_up);

}  // namespace autoblock
