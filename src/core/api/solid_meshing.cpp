#include "core/api/solid_meshing.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/io/face_selection.h"
#include "core/io/shape_file.h"
#include "core/io/svg_picture.h"
#include "core/mesh/block_model.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/geometry/edge_curve.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"

namespace autoblock {
namespace {

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Point3 point_of(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// Points along edge (edge_samples, swept_solid.h).
std::vector<Point3> edge_points(const TopoDS_Edge& edge) {
  std::vector<Point3> points;
  for (const gp_Pnt& p : edge_samples(edge)) points.push_back(point_of(p));
  return points;
}

// The bottom cap's edges with their side faces.
std::vector<SideEdge> cap_edges(const SweptSolid& s) {
  TopTools_IndexedMapOfShape numbers;
  for (size_t k = 0; k < s.faces.size(); ++k) {
    if (!s.faces[k].IsNull()) numbers.Add(s.faces[k]);
  }
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(s.solid, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  const TopoDS_Face& bottom = s.faces[static_cast<size_t>(s.bottom - 1)];
  std::vector<SideEdge> out;
  for (TopExp_Explorer it(bottom, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    SideEdge e{edge_points(edge), 0};
    for (const TopoDS_Shape& f : edge_faces.FindFromKey(edge)) {
      if (f.IsSame(bottom)) continue;
      for (size_t k = 0; k < s.faces.size(); ++k) {
        if (!s.faces[k].IsNull() && s.faces[k].IsSame(f)) e.face = static_cast<int>(k) + 1;
      }
    }
    out.push_back(e);
  }
  return out;
}

double distance_to_segment(const Point3& p, const Point3& a, const Point3& b) {
  double ab[3], ap[3], l2 = 0, t = 0;
  for (size_t k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    l2 += ab[k] * ab[k];
    t += ab[k] * ap[k];
  }
  t = l2 > 0 ? std::clamp(t / l2, 0.0, 1.0) : 0.0;
  double d2 = 0;
  for (size_t k = 0; k < 3; ++k) d2 += (ap[k] - t * ab[k]) * (ap[k] - t * ab[k]);
  return std::sqrt(d2);
}

// The longest side of the solid's box, from its vertices.
double longest_side(const TopoDS_Shape& solid) {
  Point3 low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
  auto add = [&](const Point3& p) {
    for (size_t k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  };
  for (TopExp_Explorer it(solid, TopAbs_VERTEX); it.More(); it.Next()) add(point_of(BRep_Tool::Pnt(TopoDS::Vertex(it.Current()))));
  // A curved edge (a circle, whose one vertex says nothing of its size): points along it too.
  for (TopExp_Explorer it(solid, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge) || BRepAdaptor_Curve(edge).GetType() == GeomAbs_Line) continue;
    for (const Point3& p : edge_points(edge)) add(p);
  }
  return std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2]});
}

// The solid's figures for the conformity check; tolerance, how far the cap's nodes may lie off its
// boundary (a general face's: on its lattice, as the 2-D check allows, at the tolerance its block
// model was made with: wide, kWideModelToleranceQuanta, where the cap's first mesh failed its check).
SolidFigures solid_figures(const SweptSolid& s, bool wide) {
  SolidFigures f;
  f.volume = s.volume;
  f.area = s.area;
  f.face_areas.assign(s.faces.size(), 0.0);
  f.face_perimeters.assign(s.faces.size(), 0.0);
  for (size_t k = 0; k < s.faces.size(); ++k) {
    if (s.faces[k].IsNull()) continue;
    GProp_GProps area, length;
    surface_properties(s.faces[k], s.splines, area);
    BRepGProp::LinearProperties(s.faces[k], length);
    f.face_areas[k] = area.Mass();
    f.face_perimeters[k] = length.Mass();
    const BRepAdaptor_Surface surface(s.faces[k]);
    gp_Cylinder cylinder;
    if (face_cylinder(s.faces[k], &cylinder)) {
      if (f.face_cylinders.empty()) f.face_cylinders.resize(s.faces.size());
      FaceCylinder& c = f.face_cylinders[k];
      c.origin = point_of(cylinder.Axis().Location());
      const gp_Dir axis = cylinder.Axis().Direction();
      c.axis = {axis.X(), axis.Y(), axis.Z()};
      c.radius = cylinder.Radius();
      // Convex when the face's outward normal points away from the axis.
      const double u = 0.5 * (surface.FirstUParameter() + surface.LastUParameter());
      const double v = 0.5 * (surface.FirstVParameter() + surface.LastVParameter());
      gp_Pnt p;
      gp_Vec du, dv;
      surface.D1(u, v, p, du, dv);
      gp_Vec normal = du.Crossed(dv);
      if (s.faces[k].Orientation() == TopAbs_REVERSED) normal.Reverse();
      gp_Vec radial(cylinder.Axis().Location(), p);
      radial -= gp_Vec(axis) * radial.Dot(gp_Vec(axis));
      c.convex = normal.Dot(radial) > 0;
    }
  }
  if (!f.face_cylinders.empty()) {
    f.bottom_face = s.bottom;
    f.top_face = s.top;
    gp_Dir normal;
    if (planar_face_normal(s.faces[static_cast<size_t>(s.bottom - 1)], &normal)) {
      f.cap_height = std::fabs(s.sweep.Dot(gp_Vec(normal)));
    }
  }
  if (s.cap.is_general()) f.tolerance = general_mesh_tolerance(s.cap, wide ? kWideModelToleranceQuanta : kModelToleranceQuanta);
  return f;
}

}  // namespace

MeshInput load_mesh_input(const std::string& path, int face_number, const std::string& how_to_choose) {
  const std::string what = path + ": the file";
  const std::string name = face_source_name(path, face_number);
  auto solid = [&](const TopoDS_Shape& shape) { return face_number == 0 && holds_one_solid(shape); };
  // The checks run in the reading process too, so that a crash inside them is contained there.
  const TopoDS_Shape shape = read_shape_file(path, [&](const TopoDS_Shape& read) {
    if (solid(read)) {
      swept_solid_from_shape(read, path);
    } else {
      input_face_from_occt(select_face(read, what, face_number, how_to_choose), name);
    }
  });
  MeshInput input;
  input.is_solid = solid(shape);
  if (input.is_solid) {
    input.solid = swept_solid_from_shape(shape, path);
  } else {
    input.face = input_face_from_occt(select_face(shape, what, face_number, how_to_choose), name);
  }
  return input;
}

SolidMeshing mesh_swept_solid(const SweptSolid& solid, const DecomposeSettings& settings, SolidMeshOptions options) {
  const auto start = std::chrono::steady_clock::now();
  SolidMeshing out;
  out.solid = solid;
  const double size = options.cap.size;
  if (!std::isfinite(size) || size < 0) throw InputError("the element size must be a positive number");
  if (options.layers < 0) throw InputError("the number of layers must be at least 1");
  out.default_size = !(size > 0);
  out.target_size = out.default_size ? longest_side(solid.solid) / kDefaultSizeDivisions : size;
  out.grading = options.grading;
  const double length = solid.sweep.Magnitude();
  const double wanted = options.layers > 0 ? options.layers : std::max(1.0, std::round(length / out.target_size));
  const std::vector<double> stations =
      layer_stations(wanted > 1e6 ? 1000001 : static_cast<int>(wanted), options.grading, solid.splits);
  const long layers = static_cast<long>(stations.size()) - 1;
  // The cap's quads are about its area over h^2 (as the 2-D pipeline estimates them).
  GProp_GProps cap_area;
  surface_properties(solid.faces[static_cast<size_t>(solid.bottom - 1)], solid.splines, cap_area);
  const double estimate = cap_area.Mass() / (out.target_size * out.target_size) * static_cast<double>(layers);
  if (!(estimate <= static_cast<double>(kMaxMeshHexes))) {
    throw InputError("element size " + format_significant(out.target_size, 4) + " and " + counted(layers, "layer") +
                     " would need about " + format_significant(estimate, 3) + " hexahedra (limit " +
                     std::to_string(kMaxMeshHexes) + "); choose a larger size or fewer layers");
  }
  options.cap.size = out.target_size;
  options.cap.max_quads = std::max(1L, std::min(options.cap.max_quads, kMaxMeshHexes / layers));
  out.cap = mesh_input_face(solid.cap, settings, options.cap);
  const long hexes = static_cast<long>(out.cap.result.mesh.quads.size()) * layers;
  if (hexes > kMaxMeshHexes) {
    throw InputError("element size " + format_significant(out.target_size, 4) + " and " + counted(layers, "layer") +
                     " need " + std::to_string(hexes) + " hexahedra (limit " + std::to_string(kMaxMeshHexes) +
                     "); choose a larger size or fewer layers");
  }

  auto t = std::chrono::steady_clock::now();
  SweepFrame where;
  where.frame = solid.cap.frame;
  where.sweep = {solid.sweep.X(), solid.sweep.Y(), solid.sweep.Z()};
  where.bottom_face = solid.bottom;
  where.top_face = solid.top;
  where.splits = solid.splits;
  // The side faces' edges per stretch between splits: the bottom cap's, or the solid's section in
  // the stretch's middle.
  const std::vector<std::vector<SideEdge>> stretch_edges =
      solid.splits.empty() ? std::vector<std::vector<SideEdge>>{cap_edges(solid)} : side_edges_by_stretch(solid);
  where.side_face = [&stretch_edges](const Point3& a, const Point3& b, int stretch) {
    const Point3 m{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
    int best = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (const SideEdge& e : stretch_edges[static_cast<size_t>(stretch)]) {
      for (size_t i = 0; i + 1 < e.points.size(); ++i) {
        const double d = distance_to_segment(m, e.points[i], e.points[i + 1]);
        if (d < nearest) {
          nearest = d;
          best = e.face;
        }
      }
    }
    return best;
  };
  out.mesh = sweep_quad_mesh(out.cap.result.mesh, where, stations);
  out.sweep_seconds = since(t);

  t = std::chrono::steady_clock::now();
  out.quality = hex_mesh_quality(out.mesh);
  out.conformity = check_hex_conformity(out.mesh, solid_figures(solid, out.cap.result.wide_tolerance));
  out.check_seconds = since(t);
  out.seconds = since(start);
  return out;
}

PrismBlocks solid_meshing_blocks(const SolidMeshing& m) {
  return prism_blocks(m.cap.result.model, m.solid.cap.frame, m.solid.sweep);
}

PrismBlocks swept_blocks(const SweptSolid& solid, const FaceDecomposition& decomposition) {
  if (decomposition.shape.IsNull()) throw std::logic_error("swept_blocks: the decomposition has no OpenCASCADE blocks");
  ConformalBlocks blocks;
  BRep_Builder builder;
  builder.MakeCompound(blocks.compound);
  for (TopExp_Explorer it(decomposition.shape, TopAbs_FACE); it.More(); it.Next()) {
    blocks.faces.push_back(TopoDS::Face(it.Current()));
    builder.Add(blocks.compound, it.Current());
  }
  return prism_blocks(blocks, Placement{}, solid.sweep);
}

namespace {

// Inputs: s. Output: "" or what is wrong with the solid itself where its mesh failed the check: OpenCASCADE's
// checker finds it invalid (a curve off its vertices, a face's curves on its surface not matching its
// edges), or a face's tolerance is not small against its shortest edge (within it, the face's geometry may
// disagree with its edges and the checker still pass).
std::string solid_defect(const SweptSolid& s) {
  if (!occt_shape_valid(s.solid)) {
    return "OpenCASCADE's checker finds the solid invalid (a face or an edge off its neighbours' geometry)";
  }
  for (size_t k = 0; k < s.faces.size(); ++k) {
    if (s.faces[k].IsNull()) continue;
    const double tolerance = check_finite_geometry(s.faces[k]);
    double shortest = std::numeric_limits<double>::infinity();
    for (TopExp_Explorer it(s.faces[k], TopAbs_EDGE); it.More(); it.Next()) {
      if (BRep_Tool::Degenerated(TopoDS::Edge(it.Current()))) continue;
      GProp_GProps length;
      BRepGProp::LinearProperties(it.Current(), length);
      shortest = std::min(shortest, length.Mass());
    }
    if (!(tolerance < 0.5 * shortest)) {
      return "face " + std::to_string(k + 1) + "'s OpenCASCADE tolerance " + format_number(tolerance) +
             " is not small against its shortest edge " + format_number(shortest) + " (it must be below half of it)";
    }
  }
  return "";
}

}  // namespace

void require_conformal(const SolidMeshing& m) {
  if (m.conformity.conformal) return;
  // A solid that passes the sweep's checks but whose own geometry is at fault fails the mesh's: the input's
  // fault, said so. (Looked for only here: every solid that meshes is spared the cost.)
  const std::string defect = solid_defect(m.solid);
  if (!defect.empty()) {
    throw InputError(m.solid.source + ": " + defect + ", and its hexahedral mesh does not match it (" +
                     m.conformity.problem + "); repair the shape first (FreeCAD: Part > Check geometry)");
  }
  throw std::runtime_error("the hexahedral mesh failed the conformity check: " + m.conformity.problem);
}

nlohmann::json solid_meshing_json(const std::string& input, const SolidMeshing& m) {
  const HexMeshQuality& q = m.quality;
  const HexConformity& c = m.conformity;
  const gp_Vec& d = m.solid.sweep;
  gp_Dir normal;
  double angle = 0.0;
  if (planar_face_normal(m.solid.faces[static_cast<size_t>(m.solid.bottom - 1)], &normal)) {
    angle = std::acos(std::min(1.0, std::fabs(gp_Vec(normal).Dot(d)) / d.Magnitude())) * 180.0 / M_PI;
  }
  nlohmann::json report;
  report["input"] = input;
  report["kind"] = "solid";
  report["policy"] = m.cap.policy();
  report["blocks"] = m.blocks();
  report["nodes"] = m.mesh.nodes.size();
  report["hexahedra"] = m.mesh.hexes.size();
  report["layers"] = m.mesh.layers;
  report["grading"] = m.grading;
  report["target_size"] = m.target_size;
  report["default_size"] = m.default_size;
  report["caps"] = {m.solid.bottom, m.solid.top};
  report["sweep"] = {d.X(), d.Y(), d.Z()};
  report["sweep_angle"] = angle;
  report["volume"] = m.solid.volume;
  report["area"] = m.solid.area;
  report["quality"] = {{"min_scaled_jacobian", q.min_scaled_jacobian},
                       {"mean_scaled_jacobian", q.mean_scaled_jacobian},
                       {"max_aspect_ratio", q.max_aspect_ratio},
                       {"mean_aspect_ratio", q.mean_aspect_ratio},
                       {"max_skew", q.max_skew},
                       {"edges", q.edges},
                       {"interior_edges", q.interior_edges},
                       {"irregular_edges", q.irregular_edges},
                       {"irregular_interior_edges", q.irregular_interior_edges}};
  report["conformal"] = c.conformal;
  report["conformity"] = {{"interior_faces", c.interior_faces},       {"boundary_faces", c.boundary_faces},
                          {"overused_faces", c.overused_faces},       {"misoriented_faces", c.misoriented_faces},
                          {"inverted_hexahedra", c.inverted_hexes},   {"mismatched_faces", c.mismatched_faces},
                          {"hex_volume", c.hex_volume},               {"solid_volume", c.solid_volume},
                          {"boundary_area", c.boundary_area},         {"solid_area", c.solid_area},
                          {"problem", c.problem}};
  report["seconds"] = m.seconds;
  report["timing"] = {{"cap", m.cap.seconds}, {"sweep", m.sweep_seconds}, {"checks", m.check_seconds}};
  report["cap"] = face_meshing_json(input + " (Face" + std::to_string(m.solid.bottom) + ")", m.cap);
  return report;
}

std::string solid_meshing_svg(const SolidMeshing& m, const std::string& title) {
  // Isometric view from (+1, +1, +1): screen right r, up u, towards the viewer w.
  const double s2 = std::sqrt(2.0), s6 = std::sqrt(6.0), s3 = std::sqrt(3.0);
  auto screen = [&](const Point3& p) {
    return std::array<double, 3>{(-p[0] + p[1]) / s2, (-p[0] - p[1] + 2 * p[2]) / s6, (p[0] + p[1] + p[2]) / s3};
  };
  struct Drawn {
    double depth;
    std::array<std::array<double, 3>, 4> corners;
    int block;
  };
  std::vector<Drawn> quads;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const BoundaryQuad& b : m.mesh.boundary) {
    const std::array<int, 4> f = hex_face_nodes(m.mesh.hexes[static_cast<size_t>(b.hex)], b.side);
    const Point3 v = quad_area_vector(m.mesh.nodes[static_cast<size_t>(f[0])], m.mesh.nodes[static_cast<size_t>(f[1])],
                                      m.mesh.nodes[static_cast<size_t>(f[2])], m.mesh.nodes[static_cast<size_t>(f[3])]);
    Drawn d{0.0, {}, m.mesh.hex_block[static_cast<size_t>(b.hex)]};
    for (size_t k = 0; k < 4; ++k) {
      d.corners[k] = screen(m.mesh.nodes[static_cast<size_t>(f[k])]);
      d.depth += d.corners[k][2] / 4;
      x0 = std::min(x0, d.corners[k][0]);
      x1 = std::max(x1, d.corners[k][0]);
      y0 = std::min(y0, d.corners[k][1]);
      y1 = std::max(y1, d.corners[k][1]);
    }
    if (v[0] + v[1] + v[2] > 0) quads.push_back(d);  // facing the viewer
  }
  std::sort(quads.begin(), quads.end(), [](const Drawn& a, const Drawn& b) { return a.depth < b.depth; });
  const double margin = 24, title_height = 46, target = 720;
  const double k = target / std::max({x1 - x0, y1 - y0, 1e-300});
  const double width = std::max(640.0, (x1 - x0) * k + 2 * margin), height = (y1 - y0) * k + 2 * margin + title_height;
  const double left = (width - (x1 - x0) * k) / 2;
  std::ostringstream svg;
  svg.precision(6);
  svg << svg_page_start(width, height, margin, title);
  for (const Drawn& d : quads) {
    svg << "<polygon points=\"";
    for (const auto& c : d.corners) svg << left + (c[0] - x0) * k << "," << title_height + margin + (y1 - c[1]) * k << " ";
    svg << "\" fill=\"" << block_colour(d.block) << "\" stroke=\"#333\" stroke-width=\"0.5\"/>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace autoblock
