// The value network's input: a coarse constrained Delaunay triangulation of a part, as a graph.
//
// Every model vertex (corner) of the part is a node, every boundary edge of the part is a
// constraint and holes stay empty. Two ways to add Steiner points:
//  - Bounded (the default since issue 8): each boundary edge longer than the size bound
//    (size_fraction x the longer side of the part's bounding box, so the graph does not depend on
//    the drawing's units) is split evenly into pieces no longer than it, and the constrained
//    Delaunay triangulation of those points is the graph: no refinement inside. Each edge gets at
//    most ceil(1 / size_fraction) - 1 points (2 for 0.35), so a part with V corners has at most
//    3 V nodes whatever its shape: thin features cost nothing extra (a 1:1000 strip has 8 nodes).
//  - Refined (the policies trained before issue 8; policy files without a graph method): CGAL's
//    Delaunay refinement adds Steiner points so that triangles are neither too long (the size
//    bound) nor too thin (shape criterion) and boundary edges are not encroached. A thin part then
//    needs about one node per unit of aspect ratio (a 1:32 strip dozens), capped by max_nodes.
// No CGAL and no torch in this header.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/geometry/part.h"
#include "core/geometry/point.h"

namespace autoblock {

enum class GraphMethod { Bounded, Refined };

struct GraphOptions {
  double size_fraction = 0.35;  // CGAL size criterion: triangle edges <= size_fraction * longer side of the part's bbox
  double shape_bound = 0.125;   // CGAL's shape criterion B (0.125 ~ 20.6 degrees minimum angle)
  // Refinement stops once the triangulation has this many nodes (model vertices always stay;
  // 0: no cap). The shape criterion makes thin parts expensive: a 1000:1 strip needs about 1000
  // nodes, an L with 1000:1 arms about 2000; generated faces of up to 40 rectangles and their
  // pieces need at most about 130, so the cap only bounds pathological slivers (their graph is
  // then a valid triangulation with some triangles thinner than the bound).
  int max_nodes = 1000;
  // Bounded: shape_bound is not used; max_nodes stops the edge splitting (corners always stay).
  GraphMethod method = GraphMethod::Bounded;
};

// "bounded" / "refined", and back (throws InputError for another name).
const char* graph_method_name(GraphMethod method);
GraphMethod graph_method_by_name(const std::string& name);

struct PartGraph {
  std::vector<Point2> positions;               // node coordinates (model units)
  std::vector<std::array<float, 3>> features;  // one-hot: (1,0,0) interior, (0,1,0) on a model edge, (0,0,1) model vertex
  std::vector<std::array<int, 2>> edges;       // directed (source, target); every triangulation edge in both directions
  std::vector<std::array<float, 2>> pseudo;    // per edge: (pos[source] - pos[target]) / (2 m) + 0.5, m = largest absolute component over all edges of this graph (PyG Cartesian, norm=True)
  std::vector<int> vertex_nodes;               // node index of each model vertex, in part_boundary(part) order, loops flattened

  int node_count() const { return static_cast<int>(positions.size()); }
  int edge_count() const { return static_cast<int>(edges.size()); }
};

// Inputs:  part; options (size_fraction > 0, 0 < shape_bound <= 0.125 for guaranteed termination,
//          max_nodes >= 0).
// Outputs: its coarse constrained Delaunay triangulation as a graph (options.method, see above),
//          at most 3 V nodes for V corners with the Bounded method. Every model vertex (corner) is
//          a node; every part edge is a constraint; holes are not meshed. Nodes 0 .. V-1 are the
//          model vertices in part_boundary order (so vertex_nodes[k] == k), the other nodes follow;
//          edges are sorted by (source, target). Deterministic.
// Throws std::invalid_argument for options outside those ranges.
PartGraph part_graph(const Part& part, const GraphOptions& options = {});

// Inputs:  loops, closed polygons (the outer loop and the holes of a part, disjoint, no island in a
//          hole; any orientation), their vertices the model vertices; longer_side, the longer side of
//          their bounding box (the size bound's unit); options as above.
// Outputs: the graph of part_graph for those loops: model vertices first, in the loops' order; an
//          edge is split by its Euclidean length. part_graph and region_graph (region_graph.h) are
//          this on their loops.
// Throws std::invalid_argument for options outside their ranges, std::logic_error for two vertices
// at one point.
PartGraph loops_graph(const std::vector<std::vector<Point2>>& loops, double longer_side, const GraphOptions& options = {});

}  // namespace autoblock
