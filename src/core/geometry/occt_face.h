// OpenCASCADE faces to and from PlanarFace.
#pragma once

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Dir.hxx>

#include <string>
#include <vector>

#include "core/geometry/circular_arc.h"
#include "core/geometry/placement.h"
#include "core/geometry/planar_face.h"
#include "core/geometry/validate_polygon.h"

namespace autoblock {

// The boundary of a planar face parallel to the XY plane, as read: not yet validated.
struct FaceRings {
  std::vector<RawRing> rings;    // outer wire first, then the holes, each vertex once, in wire order
  double z = 0.0;                // the face's plane
  bool normal_up = true;         // the face's normal is +Z (false: -Z)
  std::vector<CircularArc> arcs; // the circular edges, each also in its ring as its samples
                                 // (circular_arc.h: polygonise_arc without its last point)
  // Each wire's edges in order: its start vertex, the arc it is (index into arcs) or -1 (a line), and
  // the start vertex's z and OpenCASCADE tolerance (its arc's samples share them).
  struct Edge {
    Point2 start;
    int arc = -1;
    double z = 0.0;
    double tolerance = 0.0;
  };
  std::vector<std::vector<Edge>> edges;
  // The face as stored is only approximately what was read: its surface is not a plane (a spline
  // within 1e-7 of one), or an edge is a B-spline or Bezier curve read as a line or circle
  // (edge_curve.h). Its twin from face_from_rings is what the engines and OpenCASCADE then cut.
  bool approximate = false;
};

// Inputs:  face, any TopoDS_Face.
// Outputs: its wires as loops of (x, y) points, a circular edge as its samples (kArcStepDegrees
//          apart; a short arc, circular_arc.h short_arc, as one chord) and in arcs. Throws InputError when the face is not planar, does not lie parallel
//          to the XY plane, has an edge that is neither straight nor a circular arc, or an open wire
//          (naming the wire, the edge and its end points).
FaceRings read_face_rings(const TopoDS_Face& face);

// Inputs:  rings, read (read_face_rings).
// Outputs: the face they describe in the plane z = rings.z, its normal as read: straight edges as
//          lines, arcs as circles, each wire through the vertices read. Throws InputError when
//          OpenCASCADE cannot make it.
TopoDS_Face face_from_rings(const FaceRings& rings);

// Inputs: rings, read; tolerance, the face's. Throws InputError when a vertex lies off the plane by
// more than the larger of that tolerance and the vertex's own OpenCASCADE tolerance (a vertex within
// its own tolerance of the plane is on it to OpenCASCADE too: some STEP translators leave vertices a
// few thousandths off their faces, with tolerances that say so).
void check_vertices_on_plane(const FaceRings& rings, double tolerance);

// Inputs:  rings (at least one, as face_tolerance accepts).
// Outputs: true when every edge runs along X or Y within the face's tolerance (tolerance.h): the
//          face is for the grid engine; false: for the general engine (core/region).
bool rings_rectilinear(const std::vector<RawRing>& rings);

// Inputs:  face, any TopoDS_Face.
// Outputs: the face as a validated PlanarFace (read_face_rings, then validate_rings: see
//          validate_polygon.h). Throws InputError as those do.
PlanarFace planar_face_from_occt(const TopoDS_Face& face);

// Inputs:  face, any TopoDS_Face.
// Outputs: the placement of the face's own frame (placement.h), where the face lies in a plane
//          z = const: the identity when the face lies parallel to the XY plane and has an edge along X
//          or Y, or is not rectilinear in any frame (a general face keeps the model's coordinates);
//          otherwise origin at the start of its longest straight edge, X along that edge, Z along the
//          face's normal. So a face in any plane, or turned within the XY plane, is rectilinear in its
//          frame when it is rectilinear at all. A face without a straight edge (bounded by arcs and
//          circles alone) in a tilted plane: origin at its first vertex, X along its plane's X
//          direction; in the XY plane, the identity. The identity for a face that is not planar (its
//          checks then say what is wrong).
Placement face_frame(const TopoDS_Face& face);

// Inputs: face. Output: the name of its surface's type: "plane", "cylinder", "B-spline surface", ...
std::string surface_name(const TopoDS_Face& face);

// Inputs:  face.
// Outputs: true and *normal, the face's normal (its orientation applied), when the face is planar (its
//          surface is a plane or within 1e-7 of one); false otherwise.
bool planar_face_normal(const TopoDS_Face& face, gp_Dir* normal);

// Inputs: shape, in a face's frame; frame. Output: the shape in the model's coordinates (a copy of
//         its geometry moved by the frame; the shape itself for the identity).
TopoDS_Shape shape_to_model(const TopoDS_Shape& shape, const Placement& frame);

// Inputs:  polygon (outer counter-clockwise, holes clockwise), z, normal_up.
// Outputs: the face in the plane z = const with that polygon as boundary, normal +Z (or -Z).
TopoDS_Face occt_face_from_polygon(const RectilinearPolygon& polygon, double z, bool normal_up);

// Inputs:  box, z, normal_up. Output: the rectangular face (same conventions as above).
TopoDS_Face occt_rectangle(const Box& box, double z, bool normal_up);

}  // namespace autoblock
