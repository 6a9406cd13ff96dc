// The value network's input for a part of a general face (issue 12): part_graph's coarse constrained
// Delaunay triangulation, on a region's loops.
//
// Every vertex of the region's loops is a model vertex (a node with the corner feature), in the
// region's order: the outer loop, then the holes (Region::loop). An arc is the engine's chords
// (geometry/circular_arc.h: each turning by at most kArcStepDegrees, 15; an arc shorter than an
// element one chord), so its samples are model vertices too. With the bounded method an edge is
// split by its length against size_fraction x the longer side of the region's bounding box; an edge
// is at most the box's diagonal, so a part with V vertices has at most ceil(sqrt(2) / size_fraction)
// V nodes (5 V for 0.35; 3 V when its edges are axis-aligned, part_graph.h). On a rectilinear part
// the graph is part_graph's up to the lattice: the same nodes within the region's quantum and as many
// edges (which diagonal of four points on a circle is taken may differ). No CGAL and no torch in
// this header.
#pragma once

#include "core/graph/part_graph.h"
#include "core/region/region.h"

namespace autoblock {

// Inputs:  region, not empty; options (as part_graph's).
// Outputs: the graph of the region's loops (loops_graph), node k < V the k-th vertex of
//          region.loops() flattened.
// Throws std::invalid_argument for bad options or an empty region.
PartGraph region_graph(const Region& region, const GraphOptions& options = {});

}  // namespace autoblock
