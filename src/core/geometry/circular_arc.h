// Circular arcs of a face's boundary (issue 13): what the polygonal engines cut, and what the mesh
// puts its boundary nodes on.
//
// The general engine (core/region) works on polygons. A face's circular edge reaches it as a chain
// of chords: the arc polygonised so that each chord turns by at most kArcStepDegrees, every sample
// point on the arc (then on the lattice, within half a quantum of it). Each chord's ends turn by that
// step at most, which is within the block rules' flat tolerance (block.h), so the samples are side
// vertices: a block's side may run along an arc, and a block keeps a fillet corner whole. An arc
// shorter than an element at the default size is one chord instead (short_arc): a corner to the
// engines. The arcs themselves are kept beside the polygon (FaceArcs): the mesh puts its boundary
// nodes on them, not on the chords; the conformity check and the quality bound see the true boundary.
#pragma once

#include <vector>

#include "core/geometry/point.h"
#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

// How far, in lattice quanta, a point of a general face may lie off an arc's polygon and be on it
// (FaceArcs::tolerance): samples and cut ends are rounded to the lattice, within q / sqrt 2 of the
// polygon. (A T-junction is imprinted within kModelToleranceQuanta of a side, mesh/block_model.h: more,
// for the drift of many cuts' ends along one straight line.)
constexpr double kArcToleranceQuanta = 4.0;

// The largest turn of one chord of a polygonised arc, in degrees (a full circle: 24 chords).
constexpr double kArcStepDegrees = 15.0;

// The most chord steps one boundary edge of a mesh may span along a convex arc (the face inside its
// circle: a rounded corner or tip; FaceArcs::arc_of_mesh_edge): 3, 45 degrees. A mesh takes one
// interval per chord step as the minimum on an arc; a poor one is made again with that as a target
// and this as the minimum on a convex arc (mesh_region_decomposition), so that a block side holding a
// tight arc (a rounded acute tip) need not carry far more intervals than its length asks for, its
// quads fanning into the tip from the shorter side opposite. Along a hole's arc or a concave fillet
// (CircularArc::outside) one chord step stays the minimum: a hole keeps its nodes (stress
// concentrates there).
constexpr int kMeshEdgeArcSteps = 3;

struct CircularArc {
  Point2 center;
  double radius = 0.0;
  double start = 0.0;  // the angle of the arc's first point (radians, from +X, counter-clockwise)
  double sweep = 0.0;  // signed: > 0 counter-clockwise; |sweep| <= 2 pi (2 pi: a full circle)
  // The face lies outside the circle along the arc (a hole's arc, a concave fillet): its polygon is
  // circumscribed (tangents), so that the polygon's part lies inside the true face wherever the face
  // is; otherwise inscribed (chords).
  bool outside = false;
  // The number of chords of its polygon; 0: by the chord step (arc_chord_count). A short arc of a face
  // (kShortArcFraction) is one chord.
  int chords = 0;

  // Inputs: t in [0, 1]. Output: the point at start + t * sweep.
  Point2 point_at(double t) const;
  Point2 first() const { return point_at(0.0); }
  Point2 last() const { return point_at(1.0); }
  double length() const;
  // Inputs: p; tolerance. Output: 0 when p lies within tolerance (at least 1e-9 of the radius) of
  //         the arc's first point, else 1 when of its last, else -1.
  int end_at(Point2 p, double tolerance) const;
};

// Inputs:  arc; max_step_degrees, the largest turn of a chord.
// Outputs: the number of chords: arc.chords when set, else ceil(|sweep| / step), at least 2 (3 for a
//          full circle).
int arc_chord_count(const CircularArc& arc, double max_step_degrees = kArcStepDegrees);

// An arc of a face shorter than this fraction of the longer side of the face's bounding box (the
// default element size, interval_assignment.h kDefaultSizeDivisions) is polygonised as one chord
// between its ends (CircularArc::chords = 1): a fillet smaller than an element is a corner to the
// engines (a convex one a chamfer of two corners, an acute corner's a short flat end, when it turns
// by at most kShortConvexArcMaxDegrees: one chord of half a circle or more would not be one, arc_gap;
// a concave one its sharp corner, circumscribed, when it turns by at most kShortArcMaxDegrees: the
// tangents of a longer one meet far out, or not at all), where its samples would be side vertices that
// force an interval per chord (mesh_pipeline.cpp) and bunch the elements around it. Its mesh nodes
// still lie on the arc.
constexpr double kShortArcFraction = 1.0 / 20.0;
constexpr double kShortArcMaxDegrees = 120.0;
constexpr double kShortConvexArcMaxDegrees = 170.0;

// Inputs:  arc; the longer side of its face's bounding box.
// Outputs: true when it is a short arc (above): polygonised as one chord (never a full circle: it
//          turns by more than either limit).
bool short_arc(const CircularArc& arc, double face_size);

// Inputs:  arc. Outputs: its polygon, first point to last: inscribed, arc_chord_count + 1 points on
//          the arc evenly spaced in angle (a full circle's last point is its first again); circumscribed
//          (arc.outside), the first point, the n meeting points of the tangents at those samples (at
//          radius r / cos(step / 2), between them in angle; the first and last a quarter of their
//          overshoot farther out, so that a tangent join stays a vertex), and the last point.
std::vector<Point2> polygonise_arc(const CircularArc& arc, double max_step_degrees = kArcStepDegrees);

// Inputs:  p; arc; tolerance. Output: true when p lies within tolerance of the arc's polygon
//          (polygonise_arc) or of a chord between two of the arc's points at most a chord step apart:
//          between the circle through the chords' middles and the arc's circle (or, circumscribed, the
//          circle through the polygon's corners), widened by tolerance, and within the arc's angular
//          range widened by tolerance / radius at each end.
bool point_on_arc_polygon(Point2 p, const CircularArc& arc, double tolerance);

// Inputs:  p, a point near the arc's circle (not its centre). Output: p moved along the radius onto the
//          circle.
Point2 project_to_circle(Point2 p, const CircularArc& arc);

// Inputs:  arc; a -> b, a segment of its polygon (or of a mesh's boundary along it), the region on its
//          left. Outputs: the arc's length between a's and b's directions from the centre, and the area
//          the region has beyond the segment up to the arc: the sector between those directions less
//          the triangle (centre, a, b), signed (negative where the arc cuts into the segment's side).
struct ArcGap {
  double arc_length = 0.0;
  double area = 0.0;
};
ArcGap arc_gap(const CircularArc& arc, Point2 a, Point2 b);

// The arcs of a face, in the face's frame, with a lookup for the chords and points that lie on them.
struct FaceArcs {
  std::vector<CircularArc> arcs;
  double tolerance = 0.0;  // how far a point may lie off an arc and be on it (a few lattice quanta)

  bool empty() const { return arcs.empty(); }
  // Inputs: p. Output: the index of an arc whose polygon p lies on (point_on_arc_polygon within
  //         tolerance: a sample, a point of a chord, or a point already on the arc), or -1.
  int arc_of_point(Point2 p) const;
  // Inputs: p. Output: true when p is an arc's end (within tolerance, and at least 1e-9 of its radius):
  //         a vertex of the face (where two arcs of one circle meet, as CAD systems split a hole's
  //         circle in halves, or a full circle's seam), which keeps its mesh node.
  bool at_arc_end(Point2 p) const;
  // Inputs: a, b, the ends of a straight segment. Output: the index of an arc whose polygon both ends
  //         and the middle lie on, the ends at most two chord steps apart as seen from the centre (so
  //         a diameter, or a cut across the circle, is no chord of it), or -1.
  int arc_of_chord(Point2 a, Point2 b) const;
  // Inputs: a, b, the ends of a mesh's boundary edge. Output: the index of an arc that both ends lie
  //         on, at most kMeshEdgeArcSteps chord steps apart as seen from the centre (or the whole of a
  //         short arc, two of its chord steps), the edge's middle on the chord between them (inside
  //         the circle by the edge's own sagitta) and within the arc's directions; along an arc with
  //         `outside` (a hole's), as arc_of_chord; or -1. Of two such arcs (near an acute tip where
  //         two arcs meet, an edge along one lies in the other's polygon band too), the one whose
  //         circle both ends lie on.
  int arc_of_mesh_edge(Point2 a, Point2 b) const;
};

}  // namespace autoblock
