#include "core/mesh/mapped_mesh.h"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/mesh/transfinite.h"

namespace autoblock {
namespace {

struct GridPoint {
  int i = 0, j = 0;
};

int grid_index(const std::vector<double>& values, double v, double tolerance) {
  const auto it = std::lower_bound(values.begin(), values.end(), v - tolerance);
  if (it == values.end() || std::fabs(*it - v) > tolerance) {
    throw std::logic_error("mapped_mesh: a model vertex is not on the face's grid (" + std::to_string(v) + ", tolerance " + std::to_string(tolerance) + ")");
  }
  return static_cast<int>(it - values.begin());
}

// One discretised edge: node ids in increasing coordinate, from its low end to its high end.
struct EdgeNodes {
  bool horizontal = true;
  int line = 0;           // j (horizontal) or i (vertical)
  int from = 0, to = 0;   // grid range along the line
  std::vector<int> nodes;
};

}  // namespace

QuadMesh mapped_mesh(const ConformalBlocks& model, const std::vector<Box>& blocks, const GridFace& face,
                     const StripLayout& layout, const IntervalAssignment& intervals, double z,
                     double tolerance) {
  if (model.faces.size() != blocks.size()) throw std::logic_error("mapped_mesh: one face per block expected");
  const Grid& g = *layout.grid;
  tolerance = std::max(tolerance, 1e-9 * face.size);
  QuadMesh mesh;
  mesh.z = z;
  mesh.blocks = static_cast<int>(blocks.size());

  // Vertices: one node each, at its grid point's exact coordinates.
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(model.compound, TopAbs_VERTEX, vertices);
  std::vector<GridPoint> vertex_point(static_cast<size_t>(vertices.Extent()));
  for (int v = 1; v <= vertices.Extent(); ++v) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
    GridPoint& gp = vertex_point[static_cast<size_t>(v - 1)];
    gp.i = grid_index(g.xs, p.X(), tolerance);
    gp.j = grid_index(g.ys, p.Y(), tolerance);
    mesh.nodes.push_back(Point2{g.xs[static_cast<size_t>(gp.i)], g.ys[static_cast<size_t>(gp.j)]});
  }

  // Edges: the strips' nodes along them, once per edge (shared edges are one edge).
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(model.compound, TopAbs_EDGE, edges);
  std::vector<EdgeNodes> edge_nodes(static_cast<size_t>(edges.Extent()));
  for (int e = 1; e <= edges.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(e));
    const int a = vertices.FindIndex(TopExp::FirstVertex(edge)), b = vertices.FindIndex(TopExp::LastVertex(edge));
    if (a == 0 || b == 0 || a == b) throw std::logic_error("mapped_mesh: an edge without two vertices");
    GridPoint pa = vertex_point[static_cast<size_t>(a - 1)], pb = vertex_point[static_cast<size_t>(b - 1)];
    EdgeNodes& out = edge_nodes[static_cast<size_t>(e - 1)];
    out.horizontal = pa.j == pb.j;
    if (!out.horizontal && pa.i != pb.i) throw std::logic_error("mapped_mesh: an edge not parallel to an axis");
    int low = a, high = b;
    if ((out.horizontal && pb.i < pa.i) || (!out.horizontal && pb.j < pa.j)) {
      std::swap(pa, pb);
      std::swap(low, high);
    }
    out.line = out.horizontal ? pa.j : pa.i;
    out.from = out.horizontal ? pa.i : pa.j;
    out.to = out.horizontal ? pb.i : pb.j;
    const StripAxis axis = out.horizontal ? StripAxis::Column : StripAxis::Row;
    out.nodes.push_back(low - 1);
    int at = out.from;
    for (int s : strips_along(layout, axis, out.line, out.from, out.to)) {
      const Strip& strip = layout.strips[static_cast<size_t>(s)];
      if (strip.lo != at || strip.hi > out.to) throw std::logic_error("mapped_mesh: a strip sticks out of an edge");
      const std::vector<double> positions = strip_nodes(strip, intervals.intervals[static_cast<size_t>(s)]);
      for (size_t k = 1; k < positions.size(); ++k) {
        if (strip.hi == out.to && k + 1 == positions.size()) break;  // the edge's high vertex
        const double fixed = out.horizontal ? g.ys[static_cast<size_t>(out.line)] : g.xs[static_cast<size_t>(out.line)];
        out.nodes.push_back(static_cast<int>(mesh.nodes.size()));
        mesh.nodes.push_back(out.horizontal ? Point2{positions[k], fixed} : Point2{fixed, positions[k]});
      }
      at = strip.hi;
    }
    out.nodes.push_back(high - 1);
  }

  // Blocks: four logical sides from their edges, then transfinite interpolation.
  for (size_t b = 0; b < blocks.size(); ++b) {
    const Box& box = blocks[b];
    const int i0 = grid_index(g.xs, box.xmin, tolerance), i1 = grid_index(g.xs, box.xmax, tolerance);
    const int j0 = grid_index(g.ys, box.ymin, tolerance), j1 = grid_index(g.ys, box.ymax, tolerance);
    int wires = 0;
    for (TopExp_Explorer w(model.faces[b], TopAbs_WIRE); w.More(); w.Next()) ++wires;
    if (wires != 1) throw std::logic_error("mapped_mesh: block " + std::to_string(b + 1) + " is not a simple face");
    // Side k: 0 bottom, 1 top (horizontal, by x), 2 left, 3 right (vertical, by y).
    std::vector<const EdgeNodes*> sides[4];
    TopTools_IndexedMapOfShape face_edges;
    TopExp::MapShapes(model.faces[b], TopAbs_EDGE, face_edges);
    for (int e = 1; e <= face_edges.Extent(); ++e) {
      const int index = edges.FindIndex(face_edges(e));
      if (index == 0) throw std::logic_error("mapped_mesh: a block edge is not in the model");
      const EdgeNodes& en = edge_nodes[static_cast<size_t>(index - 1)];
      int side = -1;
      if (en.horizontal && en.from >= i0 && en.to <= i1) side = en.line == j0 ? 0 : en.line == j1 ? 1 : -1;
      if (!en.horizontal && en.from >= j0 && en.to <= j1) side = en.line == i0 ? 2 : en.line == i1 ? 3 : -1;
      if (side < 0) throw std::logic_error("mapped_mesh: an edge of block " + std::to_string(b + 1) + " is not on its sides");
      sides[side].push_back(&en);
    }
    std::vector<int> chain_ids[4];
    for (int side = 0; side < 4; ++side) {
      std::sort(sides[side].begin(), sides[side].end(), [](const EdgeNodes* x, const EdgeNodes* y) { return x->from < y->from; });
      int at = side < 2 ? i0 : j0;
      const int end = side < 2 ? i1 : j1;
      for (const EdgeNodes* en : sides[side]) {
        if (en->from != at) throw std::logic_error("mapped_mesh: a side of block " + std::to_string(b + 1) + " has a gap");
        for (size_t k = chain_ids[side].empty() ? 0 : 1; k < en->nodes.size(); ++k) chain_ids[side].push_back(en->nodes[k]);
        at = en->to;
      }
      if (at != end) throw std::logic_error("mapped_mesh: a side of block " + std::to_string(b + 1) + " is incomplete");
    }
    if (chain_ids[0].size() != chain_ids[1].size() || chain_ids[2].size() != chain_ids[3].size()) {
      throw std::logic_error("mapped_mesh: opposite sides of block " + std::to_string(b + 1) + " have different node counts");
    }
    add_mapped_block(mesh, chain_ids[0], chain_ids[1], chain_ids[2], chain_ids[3], static_cast<int>(b));
  }
  return mesh;
}

}  // namespace autoblock
