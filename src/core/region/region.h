// A part of a general planar face: a polygon with holes whose edges run at any angle.
//
// The robustness scheme (documented here once; every unit of core/region follows it):
//   - Every coordinate lies on the face's snapping lattice: x = round(x / q) * q, with q the
//     region's quantum (the face's tolerance, tolerance.h). Equal lattice indices are equal points,
//     so a part reached by two different cut orders is the same value, with the same hash.
//   - Constructions that create new points (cut lines crossing edges) are computed exactly (CGAL's
//     exact kernel, region_cut.h) and only then rounded to the lattice; predicates on the rounded
//     points are exact too. Rounding moves a point by at most q / 2.
//   - The canonical form: consecutive equal points merged; a vertex whose distance from the line
//     through its two neighbours is at most q removed (collinear vertices merged); loops that
//     collapse to less than three vertices or to zero area dropped; the outer ring counter-clockwise
//     and holes clockwise (the region on the left); every loop starts at its lowest, then leftmost
//     vertex; holes sorted by their first vertex.
// The grid engine (core/geometry/part.h) stays the fast path for rectilinear faces; a Region is the
// general part every policy and template of the general engine works on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry/point.h"
#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

class Region {
 public:
  Region() = default;
  // Inputs:  outer, the outer loop; holes; quantum q > 0 (the lattice spacing). Loops may have any
  //          orientation and need not be on the lattice.
  // Outputs: the region in canonical form (see above). The result may be empty (is_empty()) when
  //          the outer loop collapses.
  Region(const Ring& outer, const std::vector<Ring>& holes, double quantum);

  const Ring& outer() const { return outer_; }
  const std::vector<Ring>& holes() const { return holes_; }
  double quantum() const { return quantum_; }
  bool is_empty() const { return outer_.size() < 3; }
  int loop_count() const { return 1 + static_cast<int>(holes_.size()); }
  // Loop 0 is the outer ring, loop k >= 1 the hole k - 1.
  const Ring& loop(int k) const { return k == 0 ? outer_ : holes_[static_cast<size_t>(k - 1)]; }
  // All loops in that order: the outer ring, then the holes.
  std::vector<Ring> loops() const;
  int vertex_count() const;

  double area() const { return area_; }
  Point2 centroid() const;  // the area centroid (computed on each call)
  Box bbox() const { return ring_bbox(outer_); }
  // True when the region has no holes and no reflex corner.
  bool is_convex() const;

  bool operator==(const Region& other) const;
  bool operator!=(const Region& other) const { return !(*this == other); }
  size_t hash() const { return hash_; }

 private:
  Ring outer_;
  std::vector<Ring> holes_;
  double quantum_ = 0.0;
  double area_ = 0.0;
  size_t hash_ = 0;
};

struct RegionHash {
  size_t operator()(const Region& region) const { return region.hash(); }
};

// Inputs: value, quantum q > 0. Output: value rounded to the lattice, round(value / q) * q.
double snap_to_lattice(double value, double quantum);

// Inputs:  ring, implicitly closed; quantum q.
// Outputs: the ring in canonical form as a loop of a region (see above), orientation unchanged;
//          empty when it collapses.
Ring canonical_ring(const Ring& ring, double quantum);

// Inputs: ring (simple or weakly simple), its vertex number i. Output: the interior angle at the
//         vertex in radians, (0, 2 pi), for the region on the ring's left.
double interior_angle(const Ring& ring, size_t i);

// Inputs: ring, its vertex number i. Output: interior_angle(ring, i) > pi, decided by the sign of a
//         cross product (no trigonometry).
bool is_reflex_vertex(const Ring& ring, size_t i);

// Inputs: point x, segment a-b. Output: the distance from x to the segment.
double segment_distance(Point2 x, Point2 a, Point2 b);
// The same, squared (no square root: for comparisons on hot paths).
double segment_distance_squared(Point2 x, Point2 a, Point2 b);

// Inputs: region. Output: the total length of its loops.
double region_perimeter(const Region& region);

// Inputs: ring. Output: its area centroid (the mean of its vertices when its area is zero).
Point2 ring_centroid(const Ring& ring);

}  // namespace autoblock
