#include "core/graph/part_graph.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Handle_hash_function.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <stdexcept>
#include <utility>

#include "core/common/error.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct NodeInfo {
  int node = -1;  // graph node index, -1 until numbered
};
using VertexBase =
    CGAL::Delaunay_mesh_vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<NodeInfo, Kernel>>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;
using VertexHandle = Cdt::Vertex_handle;
using FaceHandle = Cdt::Face_handle;

// Inputs: cdt with every loop of the part inserted as constraints.
// Effect: marks as in the domain the faces inside the part: those reached from the infinite face
//         by crossing an odd number of constraints (inside the outer loop, not inside a hole). Pure
//         topology, no coordinates; it relies on the part's loops being disjoint with no island
//         inside a hole, which part_boundary guarantees for a connected part.
void mark_part_faces(Cdt& cdt) {
  std::unordered_set<FaceHandle, CGAL::Handle_hash_function> seen{cdt.infinite_face()};
  std::vector<FaceHandle> level_seeds{cdt.infinite_face()};
  for (int level = 0; !level_seeds.empty(); ++level) {
    std::vector<FaceHandle> across;  // faces behind a constraint: candidates for the next level
    std::vector<FaceHandle> stack = level_seeds;
    while (!stack.empty()) {
      const FaceHandle f = stack.back();
      stack.pop_back();
      f->set_in_domain(level % 2 == 1);
      for (int i = 0; i < 3; ++i) {
        const FaceHandle n = f->neighbor(i);
        if (seen.count(n)) continue;
        if (f->is_constrained(i)) {
          across.push_back(n);
        } else {
          seen.insert(n);
          stack.push_back(n);
        }
      }
    }
    level_seeds.clear();
    for (const FaceHandle& n : across) {
      if (seen.insert(n).second) level_seeds.push_back(n);
    }
  }
}

bool in_part(const Cdt& cdt, const FaceHandle& f) { return !cdt.is_infinite(f) && f->is_in_domain(); }

}  // namespace

const char* graph_method_name(GraphMethod method) { return method == GraphMethod::Bounded ? "bounded" : "refined"; }

GraphMethod graph_method_by_name(const std::string& name) {
  if (name == "bounded") return GraphMethod::Bounded;
  if (name == "refined") return GraphMethod::Refined;
  throw InputError("unknown graph method '" + name + "' (expected bounded or refined)");
}

PartGraph part_graph(const Part& part, const GraphOptions& options) {
  const Grid& grid = part.grid();
  std::vector<std::vector<Point2>> loops;
  for (const CornerRing& loop : part_boundary(part)) {
    std::vector<Point2>& points = loops.emplace_back();
    points.reserve(loop.size());
    for (const Corner& c : loop) points.push_back({grid.xs[static_cast<size_t>(c.i)], grid.ys[static_cast<size_t>(c.j)]});
  }
  return loops_graph(loops, part.bbox().longer_side(), options);
}

PartGraph loops_graph(const std::vector<std::vector<Point2>>& loops, double longer_side, const GraphOptions& options) {
  if (!(options.size_fraction > 0.0) || !(options.shape_bound > 0.0) || options.shape_bound > 0.125 ||
      options.max_nodes < 0) {
    throw std::invalid_argument("part_graph: size_fraction must be > 0, shape_bound in (0, 0.125], max_nodes >= 0");
  }
  const bool bounded = options.method == GraphMethod::Bounded;
  const double size_bound = options.size_fraction * longer_side;
  size_t corner_count = 0;
  for (const std::vector<Point2>& loop : loops) corner_count += loop.size();

  PartGraph graph;
  Cdt cdt;
  int corners = 0;
  size_t splits = 0;  // Bounded: edge points inserted so far
  for (const std::vector<Point2>& points : loops) {
    std::vector<VertexHandle> ring;
    ring.reserve(points.size());
    for (const Point2& p : points) {
      const VertexHandle v = cdt.insert(Kernel::Point_2(p.x, p.y));
      if (v->info().node != -1) throw std::logic_error("part_graph: two model vertices at one point");
      v->info().node = corners++;
      graph.positions.push_back(p);
      graph.features.push_back({0.f, 0.f, 1.f});
      graph.vertex_nodes.push_back(v->info().node);
      ring.push_back(v);
    }
    for (size_t k = 0; k < ring.size(); ++k) {
      const size_t next = (k + 1) % ring.size();
      VertexHandle from = ring[k];
      if (bounded) {
        // Split the edge evenly into pieces no longer than the size bound (at most
        // ceil(1 / size_fraction) - 1 points, as no edge is longer than the bounding box).
        const Point2 a = points[k], b = points[next];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const int pieces = static_cast<int>(std::ceil(length / size_bound - 1e-9));
        for (int s = 1; s < pieces; ++s) {
          if (options.max_nodes > 0 && corner_count + splits >= static_cast<size_t>(options.max_nodes)) break;
          const double t = static_cast<double>(s) / pieces;
          const VertexHandle v = cdt.insert(Kernel::Point_2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)));
          cdt.insert_constraint(from, v);
          from = v;
          ++splits;
        }
      }
      cdt.insert_constraint(from, ring[next]);
    }
  }

  mark_part_faces(cdt);
  if (!bounded) {
    Mesher mesher(cdt, Criteria(options.shape_bound, size_bound));
    mesher.init(/*domain_specified=*/true);
    if (options.max_nodes == 0) {
      mesher.refine_mesh();
    } else {
      const auto cap = static_cast<Cdt::size_type>(options.max_nodes);
      while (cdt.number_of_vertices() < cap && mesher.step_by_step_refine_mesh()) {
      }
    }
  }

  // Number the Steiner points that belong to the part's closed domain, in CGAL's vertex order.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    for (int i = 0; i < 3; ++i) {
      const VertexHandle v = f->vertex(i);
      if (v->info().node != -1) continue;
      v->info().node = -2;  // in the domain, numbered below
    }
  }
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info().node != -2) continue;
    v->info().node = static_cast<int>(graph.positions.size());
    graph.positions.push_back(Point2{v->point().x(), v->point().y()});
    const bool on_edge = cdt.are_there_incident_constraints(v);
    graph.features.push_back(on_edge ? std::array<float, 3>{0.f, 1.f, 0.f} : std::array<float, 3>{1.f, 0.f, 0.f});
  }

  // Edges of the part's triangles, both ways.
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    const FaceHandle f = e->first;
    const FaceHandle g = f->neighbor(e->second);
    if (!in_part(cdt, f) && !in_part(cdt, g)) continue;
    const int a = f->vertex(Cdt::cw(e->second))->info().node;
    const int b = f->vertex(Cdt::ccw(e->second))->info().node;
    if (a < 0 || b < 0) throw std::logic_error("part_graph: an edge of the part has an unnumbered end");
    graph.edges.push_back({a, b});
    graph.edges.push_back({b, a});
  }
  std::sort(graph.edges.begin(), graph.edges.end());

  double m = 0.0;
  for (const auto& [s, t] : graph.edges) {
    const Point2& ps = graph.positions[static_cast<size_t>(s)];
    const Point2& pt = graph.positions[static_cast<size_t>(t)];
    m = std::max({m, std::abs(ps.x - pt.x), std::abs(ps.y - pt.y)});
  }
  graph.pseudo.reserve(graph.edges.size());
  for (const auto& [s, t] : graph.edges) {
    const Point2& ps = graph.positions[static_cast<size_t>(s)];
    const Point2& pt = graph.positions[static_cast<size_t>(t)];
    graph.pseudo.push_back({static_cast<float>((ps.x - pt.x) / (2.0 * m) + 0.5),
                            static_cast<float>((ps.y - pt.y) / (2.0 * m) + 0.5)});
  }
  return graph;
}

}  // namespace autoblock
