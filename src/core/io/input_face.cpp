#include "core/io/input_face.h"

#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/geometry/occt_face.h"
#include "core/io/face_selection.h"
#include "core/io/shape_file.h"
#include "core/region/validate_region.h"

namespace autoblock {
namespace {

bool finite(double v) { return std::isfinite(v); }
bool finite(const gp_XYZ& p) { return finite(p.X()) && finite(p.Y()) && finite(p.Z()); }
bool finite(const gp_Pnt& p) { return finite(p.XYZ()); }
bool finite(const gp_Pnt2d& p) { return finite(p.X()) && finite(p.Y()); }

}  // namespace

// Every number OpenCASCADE computes with is finite and consistent before it computes anything
// that loops on a bad parameter (projections, periodic adjustments): tolerances (finite, not
// negative), the surface at its origin, each edge's parameter range (finite, increasing) and its
// 3-D curve's ends on the edge's vertices, its curve on the face, the vertices near enough to the
// surface's origin for precise parameters. Returns the largest tolerance.
// Throws InputError.
double check_finite_geometry(const TopoDS_Face& face) {
  auto tolerance_ok = [](double t) { return finite(t) && t >= 0; };
  double largest = BRep_Tool::Tolerance(face);
  if (!tolerance_ok(largest)) throw InputError("the face's tolerance is " + format_number(largest));
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (surface.IsNull()) throw InputError("the face has no surface");
  gp_Pnt origin;
  gp_Vec du, dv;
  surface->D1(0.0, 0.0, origin, du, dv);
  if (!finite(origin) || !finite(du.XYZ()) || !finite(dv.XYZ())) {
    throw InputError("the face's surface is not finite at its origin");
  }
  int number = 0;
  double farthest = 0.0;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    const std::string name = "edge " + std::to_string(++number);
    const double tolerance = BRep_Tool::Tolerance(edge);
    if (!tolerance_ok(tolerance)) throw InputError(name + " has the tolerance " + format_number(tolerance));
    largest = std::max(largest, tolerance);
    if (BRep_Tool::Degenerated(edge)) continue;
    double first = 0, last = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    if (curve.IsNull()) throw InputError(name + " has no 3-D curve");
    if (!finite(first) || !finite(last) || !(first < last)) {
      throw InputError(name + " has the parameter range [" + format_number(first) + ", " + format_number(last) + "]");
    }
    TopoDS_Vertex start, end;
    TopExp::Vertices(edge, start, end);
    if (start.IsNull() || end.IsNull()) throw InputError(name + " lacks a vertex");
    const gp_Pnt a = curve->Value(first), b = curve->Value(last);
    const gp_Pnt p = BRep_Tool::Pnt(start), q = BRep_Tool::Pnt(end);
    const double slack = tolerance + std::max(BRep_Tool::Tolerance(start), BRep_Tool::Tolerance(end));
    if (!finite(a) || !finite(b) || !finite(p) || !finite(q) || !(a.Distance(p) <= slack) || !(b.Distance(q) <= slack)) {
      throw InputError(name + "'s curve does not run between its vertices");
    }
    const Handle(Geom2d_Curve) on_surface = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (!on_surface.IsNull() && (!finite(first) || !finite(last) || !finite(on_surface->Value(first)) ||
                                 !finite(on_surface->Value(last)))) {
      throw InputError(name + "'s curve on the face has a parameter range or an end point that is not finite");
    }
  }
  for (TopExp_Explorer it(face, TopAbs_VERTEX); it.More(); it.Next()) {
    const TopoDS_Vertex& vertex = TopoDS::Vertex(it.Current());
    const double tolerance = BRep_Tool::Tolerance(vertex);
    if (!tolerance_ok(tolerance)) throw InputError("a vertex has the tolerance " + format_number(tolerance));
    const gp_Pnt point = BRep_Tool::Pnt(vertex);
    if (!finite(point)) throw InputError("a vertex has a coordinate that is not finite");
    largest = std::max(largest, tolerance);
    farthest = std::max(farthest, point.Distance(origin));
  }
  // Parameters on the surface are distances from its origin: far away, their rounding error
  // (about 1e-16 of the distance, times what OpenCASCADE's algorithms lose) exceeds the fixed
  // precision its algorithms work to (Precision::Confusion(), 1e-7), whatever the tolerances say.
  if (farthest * 1e-15 > Precision::Confusion()) {
    throw InputError("the face lies " + format_number(farthest) +
                     " away from its surface's origin: too far for OpenCASCADE to compute on it precisely");
  }
  return largest;
}

namespace {

// The smallest distance between two distinct grid coordinates: the face's smallest feature.
double smallest_feature(const Grid& grid) {
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < grid.columns(); ++i) smallest = std::min(smallest, grid.cell_width(i));
  for (int j = 0; j < grid.rows(); ++j) smallest = std::min(smallest, grid.cell_height(j));
  return smallest;
}

// The shortest edge of a general face: its smallest feature.
double smallest_feature(const Region& region) {
  double smallest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < region.loop_count(); ++k) {
    const Ring& ring = region.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % ring.size()];
      smallest = std::min(smallest, std::hypot(b.x - a.x, b.y - a.y));
    }
  }
  return smallest;
}

// The face's vertices between two straight edges (as read) that the region leaves out, on its
// lattice: a vertex between two edges in line, which the region's canonical form merges. (An arc's
// ends are its polygon's first and last samples; a full circle's seam is no corner of anything.)
std::vector<Point2> straight_vertices(const FaceRings& read, const Region& region) {
  const double q = region.quantum();
  std::vector<Point2> kept;
  for (int k = 0; k < region.loop_count(); ++k) kept.insert(kept.end(), region.loop(k).begin(), region.loop(k).end());
  auto before = [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  std::sort(kept.begin(), kept.end(), before);
  std::vector<Point2> left_out;
  for (const auto& wire : read.edges) {
    for (size_t e = 0; e < wire.size(); ++e) {
      const FaceRings::Edge& edge = wire[e];
      if (edge.arc >= 0 || wire[(e + wire.size() - 1) % wire.size()].arc >= 0) continue;  // an arc's end
      const Point2 p{snap_to_lattice(edge.start.x, q), snap_to_lattice(edge.start.y, q)};
      if (!std::binary_search(kept.begin(), kept.end(), p, before)) left_out.push_back(p);
    }
  }
  return left_out;
}

// The same for a rectilinear face: its vertices that the polygon leaves out, each coordinate snapped
// to the polygon's own within tolerance (as the polygon's are, validate_polygon.h).
std::vector<Point2> straight_vertices(const FaceRings& read, const RectilinearPolygon& polygon, double tolerance) {
  std::vector<double> xs, ys;
  std::vector<Point2> kept = polygon.outer;
  for (const Ring& hole : polygon.holes) kept.insert(kept.end(), hole.begin(), hole.end());
  for (const Point2& p : kept) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  auto snapped = [&](double v, const std::vector<double>& values) {
    double best = v, distance = tolerance;
    for (double w : values) {
      if (std::fabs(w - v) <= distance) {
        distance = std::fabs(w - v);
        best = w;
      }
    }
    return best;
  };
  std::vector<Point2> left_out;
  for (const auto& wire : read.edges) {
    for (const FaceRings::Edge& edge : wire) {  // (no arcs: the face is a polygon)
      const Point2 p{snapped(edge.start.x, xs), snapped(edge.start.y, ys)};
      const bool kept_vertex = std::any_of(kept.begin(), kept.end(), [&](Point2 k) {
        return std::fabs(k.x - p.x) <= tolerance && std::fabs(k.y - p.y) <= tolerance;
      });
      if (!kept_vertex) left_out.push_back(p);
    }
  }
  return left_out;
}

// What OpenCASCADE needs beyond the polygon checks before it cuts the face (tolerance, the largest
// of its tolerances, from check_finite_geometry; feature, the face's smallest feature): a face its
// own checker accepts (edges on their vertices, curves on the surface, ...), with tolerances small
// against the face's smallest feature (else its fuzzy intersections merge what the engines keep
// apart, or run for ever). Throws InputError.
void check_occt_face(const TopoDS_Face& face, double tolerance, double feature) {
  if (!(tolerance < 0.5 * feature)) {
    throw InputError("the face's OpenCASCADE tolerance " + format_number(tolerance) +
                     " is not small against its smallest feature " + format_number(feature) +
                     " (it must be below half of it)");
  }
  if (!BRepCheck_Analyzer(face).IsValid()) {
    throw InputError("OpenCASCADE's checker finds the face invalid (an edge off its vertices or its surface, "
                     "a broken wire or curve)");
  }
}

// The face carried into its frame (a copy of its geometry); the face itself for the identity.
TopoDS_Face face_in_frame(const TopoDS_Face& face, const Placement& frame) {
  if (frame.identity()) return face;
  BRepBuilderAPI_Transform move(face, frame.to_frame(), true);
  if (!move.IsDone()) throw InputError("OpenCASCADE cannot carry the face into its own frame");
  return TopoDS::Face(move.Shape());
}

}  // namespace

InputFace load_input_face(const std::string& path, int face_number, const std::string& how_to_choose) {
  const std::string what = path + ": the file";
  const std::string name = face_source_name(path, face_number);
  // The checks run in the reading process too, so that a crash inside them is contained there.
  const TopoDS_Shape shape = read_shape_file(path, [&](const TopoDS_Shape& read) {
    input_face_from_occt(select_face(read, what, face_number, how_to_choose), name);
  });
  return input_face_from_occt(select_face(shape, what, face_number, how_to_choose), name);
}

InputFace input_face_from_brep_text(const std::string& text, const std::string& source) {
  TopoDS_Shape shape;
  try {
    shape = read_brep_text(text, [&](const TopoDS_Shape& read) { input_face_from_occt(select_face(read, source, 0), source); });
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.rfind(source, 0) == 0) throw;
    throw InputError(source + ": " + message);  // the reader's messages do not know the source
  }
  return input_face_from_occt(select_face(shape, source, 0), source);
}

InputFace input_face_from_occt(const TopoDS_Face& face, const std::string& source) {
  InputFace input;
  input.source = source;
  input.model = face;
  input.occt = face;
  try {
    const double tolerance = face.IsNull() ? 0.0 : check_finite_geometry(face);
    if (!face.IsNull()) {
      input.frame = face_frame(face);
      input.occt = face_in_frame(face, input.frame);
    }
    const FaceRings read = read_face_rings(input.occt);
    // A face stored as splines that are a plane, lines and circles: cut and meshed as what it is.
    if (read.approximate) input.occt = face_from_rings(read);
    input.planar.z = read.z;
    input.planar.normal_up = read.normal_up;
    if (read.arcs.empty() && rings_rectilinear(read.rings)) {
      input.planar.polygon = validate_rings(read.rings, &input.planar.tolerance);
      check_vertices_on_plane(read, input.planar.tolerance);
      input.grid = make_grid_face(input.planar.polygon);
      input.straight_vertices = straight_vertices(read, input.planar.polygon, input.planar.tolerance);
      check_occt_face(input.occt, tolerance, smallest_feature(*input.grid.grid));
    } else {
      input.region = validate_general_rings(read.rings, &input.planar.tolerance);
      input.arcs.arcs = read.arcs;
      input.straight_vertices = straight_vertices(read, input.region);
      // Samples and cut ends lie on the lattice (within q / sqrt 2 of where they belong), T-junctions
      // within kModelToleranceQuanta quanta of a side (block_model.h).
      input.arcs.tolerance = kArcToleranceQuanta * input.region.quantum();
      check_vertices_on_plane(read, input.planar.tolerance);
      check_occt_face(input.occt, tolerance, smallest_feature(input.region));
    }
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  } catch (const Standard_Failure& e) {
    // A face OpenCASCADE itself cannot evaluate (no geometry, a broken surface): the input's fault.
    throw InputError(source + ": OpenCASCADE cannot evaluate the face (" + e.DynamicType()->Name() + ": " +
                     e.GetMessageString() + ")");
  }
  return input;
}

void require_rectilinear(const InputFace& face, const std::string& what, const std::string& instead) {
  if (face.is_general()) {
    throw InputError(face.source + ": " + what +
                     " works on faces whose edges run along two perpendicular directions; this face has edges at "
                     "other angles (" + (instead.empty() ? "decompose it with the general engine: policies auto, search, greedy, random" : instead) + ")");
  }
}

}  // namespace autoblock
