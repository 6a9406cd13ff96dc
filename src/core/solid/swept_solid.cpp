#include "core/solid/swept_solid.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Precision.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Dir.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/geometry/edge_curve.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"

namespace autoblock {
namespace {

int count_of(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape map;
  if (!shape.IsNull()) TopExp::MapShapes(shape, type, map);
  return map.Extent();
}

std::string point_text(const gp_Pnt& p, double tolerance) {
  return "(" + format_number(p.X(), tolerance) + ", " + format_number(p.Y(), tolerance) + ", " +
         format_number(p.Z(), tolerance) + ")";
}

std::string vector_text(const gp_Vec& v, double tolerance) { return point_text(gp_Pnt(v.XYZ()), tolerance); }

std::string face_name(int number) { return "face " + std::to_string(number); }

// Throws when a face of shell has an edge no other face shares (an open shell), naming the face.
void require_closed(const TopoDS_Shape& shell, const TopTools_IndexedMapOfShape& numbers, double tolerance) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(shell, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int e = 1; e <= edge_faces.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(edge_faces.FindKey(e));
    const TopTools_ListOfShape& faces = edge_faces(e);
    if (BRep_Tool::Degenerated(edge) || faces.Extent() != 1) continue;
    const TopoDS_Face& face = TopoDS::Face(faces.First());
    if (BRep_Tool::IsClosed(edge, face)) continue;  // a seam: both sides are the same face
    TopoDS_Vertex a, b;
    TopExp::Vertices(edge, a, b);
    throw InputError("the shell is open: " + face_name(numbers.FindIndex(face)) + " has a free edge from " +
                     point_text(BRep_Tool::Pnt(a), tolerance) + " to " + point_text(BRep_Tool::Pnt(b), tolerance) +
                     " that no other face shares (a swept solid is closed)");
  }
}

// The solid of shape (its only solid, or its only shell closed into one), oriented outwards.
TopoDS_Solid the_solid(const TopoDS_Shape& shape, const TopTools_IndexedMapOfShape& numbers, double tolerance) {
  const int solids = count_of(shape, TopAbs_SOLID);
  if (solids > 1) {
    throw InputError("the file holds " + std::to_string(solids) + " solids; a swept solid is exactly one solid");
  }
  TopoDS_Solid solid;
  if (solids == 1) {
    TopExp_Explorer it(shape, TopAbs_SOLID);
    solid = TopoDS::Solid(it.Current());
    const int shells = count_of(solid, TopAbs_SHELL);
    if (shells != 1) {
      throw InputError("the solid has " + std::to_string(shells) +
                       " shells (a cavity inside it); a swept solid has one closed shell");
    }
    require_closed(solid, numbers, tolerance);
  } else {
    const int shells = count_of(shape, TopAbs_SHELL);
    if (shells != 1) {
      throw InputError("the file holds no solid and " + counted(shells, "shell") + "; a swept solid is one closed solid");
    }
    TopExp_Explorer it(shape, TopAbs_SHELL);
    const TopoDS_Shell shell = TopoDS::Shell(it.Current());
    require_closed(shell, numbers, tolerance);
    BRepBuilderAPI_MakeSolid make(shell);
    if (!make.IsDone()) throw InputError("OpenCASCADE cannot make a solid of the closed shell");
    solid = make.Solid();
  }
  BRepClass3d_SolidClassifier classifier(solid);
  classifier.PerformInfinitePoint(Precision::Confusion());
  if (classifier.State() == TopAbs_IN) solid.Reverse();
  return solid;
}

struct CapFace {
  int number = 0;
  gp_Dir normal;  // outward
  double area = 0.0;
  double perimeter = 0.0;
  gp_Pnt centroid;
  std::vector<gp_Pnt> vertices;
};

// Whether a surface or curve of the shape is a B-spline or Bezier one.
bool has_splines(const TopoDS_Shape& shape) {
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    const GeomAbs_SurfaceType type = BRepAdaptor_Surface(TopoDS::Face(it.Current()), false).GetType();
    if (type == GeomAbs_BSplineSurface || type == GeomAbs_BezierSurface) return true;
  }
  for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge)) continue;
    const GeomAbs_CurveType type = BRepAdaptor_Curve(edge).GetType();
    if (type == GeomAbs_BSplineCurve || type == GeomAbs_BezierCurve) return true;
  }
  return false;
}

CapFace cap_face(const TopoDS_Face& face, int number, const gp_Dir& normal, bool splines) {
  CapFace c;
  c.number = number;
  c.normal = normal;
  GProp_GProps properties;
  surface_properties(face, splines, properties);
  c.area = properties.Mass();
  c.centroid = properties.CentreOfMass();
  GProp_GProps length;
  BRepGProp::LinearProperties(face, length);
  c.perimeter = length.Mass();
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
  for (int v = 1; v <= vertices.Extent(); ++v) c.vertices.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertices(v))));
  return c;
}

// A side face that is a cylinder (an extruded arc or round hole): its number and axis direction.
struct CylinderFace {
  int number = 0;
  gp_Dir axis;
};

// A pair of opposite faces tried as caps: how far it got (0 caps differ, 1 a side is not parallel,
// 2 volume differs, 3 a side face is split across the sweep where the layers cannot follow, 4 good) and why it stopped.
struct CapTrial {
  int stage = 0;
  std::string why;
  const CapFace* bottom = nullptr;
  const CapFace* top = nullptr;
  gp_Vec sweep;
  std::vector<double> splits;  // SweptSolid::splits
};

// An edge of a side face that runs across the sweep: its face's number and its ends.
struct EdgeAcross {
  int face = 0;
  gp_Pnt from, to;
};

// Where the side faces are split across the sweep: the heights of the splits, or why the layers
// cannot follow them.
struct SideSplits {
  std::vector<double> heights;          // fractions of the sweep in (0, 1), increasing
  std::optional<EdgeAcross> slanting;   // an edge across the sweep not at one height
  std::optional<EdgeAcross> off_column; // a vertex between the caps over no vertex of the bottom cap
                                        // (from: the vertex, to: the point below it)
};

// Inputs: faces, the solid's (by number - 1); bottom, top, the caps; sweep; tolerance.
// Output: where the side faces are split across the sweep (two faces where one would do, as a fusion
// of stacked boxes leaves them): the heights of their vertices strictly between the caps' planes. A
// straight sweep has none: its side faces are bounded by the caps' edges and lines along the sweep.
// The layers can follow a split whose edges across the sweep (not straight along it) lie at one
// height (every point, sampled) and whose vertices lie over the bottom cap's vertices (where the
// cap's mesh has nodes; a full circle's seam vertex excepted, as the cap's own); the first edge or
// vertex that does not is returned instead.
SideSplits side_splits(const std::vector<TopoDS_Face>& faces, const CapFace& bottom, const CapFace& top,
                       const gp_Vec& sweep, double tolerance) {
  SideSplits out;
  const gp_Vec normal(bottom.normal);
  const double height = sweep.Dot(normal);
  if (std::fabs(height) <= tolerance) return out;
  auto level = [&](const gp_Pnt& p) { return gp_Vec(bottom.centroid, p).Dot(normal); };
  auto between = [&](double along) { return std::fabs(along) > tolerance && std::fabs(along - height) > tolerance; };
  for (size_t k = 0; k < faces.size(); ++k) {
    const int number = static_cast<int>(k) + 1;
    if (number == bottom.number || number == top.number || faces[k].IsNull()) continue;
    TopTools_IndexedMapOfShape seams;  // the vertices of closed edges (full circles)
    for (TopExp_Explorer it(faces[k], TopAbs_EDGE); it.More(); it.Next()) {
      const TopoDS_Edge edge = TopoDS::Edge(it.Current());
      if (BRep_Tool::Degenerated(edge)) continue;
      BRepAdaptor_Curve curve(edge);
      const gp_Pnt middle = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
      const double along = level(middle);
      if (!between(along)) continue;  // in a cap's plane
      // Along the sweep: straight from end to end (a line, or a translator's B-spline that is one) in
      // the sweep's direction.
      const gp_Pnt a = curve.Value(curve.FirstParameter()), b = curve.Value(curve.LastParameter());
      const gp_Vec chord(a, b);
      const double off_line = chord.Magnitude() > tolerance ? gp_Vec(a, middle).Crossed(chord).Magnitude() / chord.Magnitude() : 0.0;
      if (chord.Crossed(sweep).Magnitude() <= tolerance * sweep.Magnitude() && off_line <= tolerance) continue;
      if (a.Distance(b) <= tolerance) TopExp::MapShapes(edge, TopAbs_VERTEX, seams);
      constexpr int kSamples = 16;
      bool level_edge = true;
      for (int i = 0; i <= kSamples && level_edge; ++i) {
        const double u = curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / kSamples;
        level_edge = std::fabs(level(curve.Value(u)) - along) <= tolerance;
      }
      if (!level_edge && !out.slanting) out.slanting = EdgeAcross{number, a, b};
    }
    TopTools_IndexedMapOfShape vertices;
    TopExp::MapShapes(faces[k], TopAbs_VERTEX, vertices);
    for (int v = 1; v <= vertices.Extent(); ++v) {
      const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
      const double along = level(p);
      if (!between(along)) continue;
      const double at = along / height;
      const bool known = std::any_of(out.heights.begin(), out.heights.end(),
                                     [&](double h) { return std::fabs(h - at) * std::fabs(height) <= tolerance; });
      if (!known) out.heights.push_back(at);
      if (seams.Contains(vertices(v)) || out.off_column) continue;
      const gp_Pnt below = p.Translated(-sweep * at);
      const bool over_vertex = std::any_of(bottom.vertices.begin(), bottom.vertices.end(),
                                           [&](const gp_Pnt& q) { return q.Distance(below) <= tolerance; });
      if (!over_vertex) out.off_column = EdgeAcross{number, p, below};
    }
  }
  std::sort(out.heights.begin(), out.heights.end());
  return out;
}

CapTrial try_caps(const CapFace& bottom, const CapFace& top, const std::vector<CapFace>& planar,
                  const std::vector<CylinderFace>& cylinders, const std::vector<TopoDS_Face>& faces, double volume,
                  double tolerance) {
  CapTrial t;
  t.bottom = &bottom;
  t.top = &top;
  t.sweep = gp_Vec(bottom.centroid, top.centroid);
  const std::string pair = face_name(bottom.number) + " and " + face_name(top.number);
  const double scale = std::max(bottom.area, top.area);
  // Within the shape's tolerance along the boundary: a translator's B-spline circles stray by their
  // edges' tolerance (CATIA's: 2.6e-5), so two caps' areas may differ by that times the perimeter.
  const double slack = tolerance * std::max(bottom.perimeter, top.perimeter);
  if (std::fabs(bottom.area - top.area) > std::max(1e-7 * scale, slack)) {
    t.why = "the caps differ: " + pair + " are parallel and opposite but not translated copies of each other (areas " +
            format_significant(bottom.area, 6) + " and " + format_significant(top.area, 6) + ")";
    return t;
  }
  if (bottom.vertices.size() != top.vertices.size()) {
    t.why = "the caps differ: " + pair + " are parallel and opposite but not translated copies of each other (" +
            counted(static_cast<long long>(bottom.vertices.size()), "vertex", "vertices") + " and " +
            std::to_string(top.vertices.size()) + ")";
    return t;
  }
  for (const gp_Pnt& p : bottom.vertices) {
    const gp_Pnt moved = p.Translated(t.sweep);
    const bool found = std::any_of(top.vertices.begin(), top.vertices.end(),
                                   [&](const gp_Pnt& q) { return q.Distance(moved) <= tolerance; });
    if (!found) {
      t.why = "the caps differ: " + pair + " are parallel and opposite but not translated copies of each other (" +
              face_name(bottom.number) + "'s vertex " + point_text(p, tolerance) + " moved by " +
              vector_text(t.sweep, tolerance) + " is no vertex of " + face_name(top.number) + ")";
      return t;
    }
  }
  t.stage = 1;
  const gp_Dir direction(t.sweep);
  for (const CapFace& side : planar) {
    if (side.number == bottom.number || side.number == top.number) continue;
    const double sine = std::fabs(side.normal.Dot(direction));
    if (sine > 1e-7) {
      t.why = face_name(side.number) + " is not parallel to the sweep " + vector_text(t.sweep, tolerance) + " from " +
              face_name(bottom.number) + " to " + face_name(top.number) + " (it makes " +
              format_significant(std::asin(std::min(1.0, sine)) * 180.0 / M_PI, 3) +
              " degrees with it): a swept solid's side faces run along the sweep";
      return t;
    }
  }
  for (const CylinderFace& side : cylinders) {
    const double sine = gp_Vec(side.axis).Crossed(gp_Vec(direction)).Magnitude();
    if (sine > 1e-7) {
      t.why = face_name(side.number) + ", a cylinder, does not run along the sweep " + vector_text(t.sweep, tolerance) +
              " from " + face_name(bottom.number) + " to " + face_name(top.number) + " (its axis makes " +
              format_significant(std::asin(std::min(1.0, sine)) * 180.0 / M_PI, 3) +
              " degrees with it): a swept solid's side faces run along the sweep";
      return t;
    }
  }
  t.stage = 2;
  const double expected = bottom.area * std::fabs(t.sweep.Dot(gp_Vec(bottom.normal)));
  if (std::fabs(volume - expected) > std::max(1e-6 * std::max(volume, expected), slack * t.sweep.Magnitude())) {
    t.why = "the solid is not the sweep of " + face_name(bottom.number) + " along " + vector_text(t.sweep, tolerance) +
            ": its volume " + format_significant(volume, 6) + " differs from the cap's area times the height, " +
            format_significant(expected, 6);
    return t;
  }
  t.stage = 3;
  // A side face split across the sweep (two faces where one would do, as a fusion of stacked boxes
  // leaves them): the layers follow a split at one height over the cap's vertices, and nothing else.
  const SideSplits splits = side_splits(faces, bottom, top, t.sweep, tolerance);
  const std::string remedy = "; merge the split faces first (FreeCAD: Part > Create a copy > Refine shape) or mesh the faces one by one";
  if (const auto& e = splits.slanting) {
    t.why = face_name(e->face) + " is split across the sweep from " + face_name(bottom.number) + " to " +
            face_name(top.number) + " by an edge that slants (from " + point_text(e->from, tolerance) + " to " +
            point_text(e->to, tolerance) + "): the sweep's layers cannot follow it" + remedy;
    return t;
  }
  if (const auto& e = splits.off_column) {
    t.why = face_name(e->face) + " is split across the sweep from " + face_name(bottom.number) + " to " +
            face_name(top.number) + " at a vertex " + point_text(e->from, tolerance) + " over no vertex of " +
            face_name(bottom.number) + " (it lies over " + point_text(e->to, tolerance) +
            "): the sweep's columns of nodes cannot meet it" + remedy;
    return t;
  }
  t.splits = splits.heights;
  t.stage = 4;
  return t;
}

// Inputs: solid, one that is no swept solid as it is; faces, its face count.
// Output: "" or, when merging its faces that could be one (coplanar or co-cylindrical neighbours, as a
// fusion without refining leaves them; OpenCASCADE's ShapeUpgrade_UnifySameDomain, as FreeCAD's Refine
// shape) leaves fewer faces and a swept solid, a hint that says so and how.
std::string refine_hint(const TopoDS_Solid& solid, int faces) {
  try {
    ShapeUpgrade_UnifySameDomain unify(solid, true, true, false);
    unify.Build();
    const TopoDS_Shape merged = unify.Shape();
    const int after = count_of(merged, TopAbs_FACE);
    if (merged.IsNull() || after >= faces) return "";
    swept_solid_from_shape(merged, "refined");  // throws when merged it is no sweep either
    return "; merging its faces that could be one (" + std::to_string(faces) + " faces into " + std::to_string(after) +
           ", as boxes fused without refining leave them split) makes it a swept solid: merge them first (FreeCAD: "
           "Part > Create a copy > Refine shape)";
  } catch (const std::exception&) {
    return "";
  } catch (const Standard_Failure&) {
    return "";
  }
}

}  // namespace

std::vector<gp_Pnt> edge_samples(const TopoDS_Edge& edge) {
  const BRepAdaptor_Curve curve(edge);
  const int n = curve.GetType() == GeomAbs_Line ? 1 : kEdgeSamples;
  std::vector<gp_Pnt> points;
  for (int i = 0; i <= n; ++i) points.push_back(curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / n));
  return points;
}

void surface_properties(const TopoDS_Shape& shape, bool splines, GProp_GProps& properties) {
  if (splines) {
    BRepGProp::SurfaceProperties(shape, properties, kPropertiesPrecision);
  } else {
    BRepGProp::SurfaceProperties(shape, properties);
  }
}

void volume_properties(const TopoDS_Shape& shape, bool splines, GProp_GProps& properties) {
  if (splines) {
    BRepGProp::VolumeProperties(shape, properties, kPropertiesPrecision);
  } else {
    BRepGProp::VolumeProperties(shape, properties);
  }
}

std::vector<std::vector<SideEdge>> side_edges_by_stretch(const SweptSolid& s) {
  const TopoDS_Face& bottom = s.faces[static_cast<size_t>(s.bottom - 1)];
  gp_Dir normal;
  if (!planar_face_normal(bottom, &normal)) throw std::logic_error("swept solid: the bottom cap is not planar");
  TopExp_Explorer first(bottom, TopAbs_VERTEX);
  const gp_Pnt origin = BRep_Tool::Pnt(TopoDS::Vertex(first.Current()));
  std::vector<double> middles;
  for (size_t k = 0; k <= s.splits.size(); ++k) {
    middles.push_back(0.5 * ((k == 0 ? 0.0 : s.splits[k - 1]) + (k == s.splits.size() ? 1.0 : s.splits[k])));
  }
  BRep_Builder builder;
  TopoDS_Compound sides, planes;
  builder.MakeCompound(sides);
  builder.MakeCompound(planes);
  for (size_t k = 0; k < s.faces.size(); ++k) {
    if (!s.faces[k].IsNull() && static_cast<int>(k) + 1 != s.bottom && static_cast<int>(k) + 1 != s.top) builder.Add(sides, s.faces[k]);
  }
  // Plane faces reaching past the solid: twice its bounding box's diagonal.
  Bnd_Box box;
  BRepBndLib::Add(s.solid, box);
  const double reach = 2.0 * std::sqrt(box.SquareExtent());
  std::vector<TopoDS_Face> plane_faces;
  for (double at : middles) {
    const gp_Pln plane(origin.Translated(s.sweep * at), normal);
    plane_faces.push_back(BRepBuilderAPI_MakeFace(plane, -reach, reach, -reach, reach).Face());
    builder.Add(planes, plane_faces.back());
  }
  BRepAlgoAPI_Section section(sides, planes, false);
  section.ComputePCurveOn1(false);
  section.Approximation(false);
  const std::string failed = s.source + ": OpenCASCADE cannot cut the solid's sides between the splits across its sweep";
  try {
    section.Build();
  } catch (const Standard_Failure& e) {
    throw std::runtime_error(failed + " (" + e.DynamicType()->Name() + ")");
  }
  if (!section.IsDone()) throw std::runtime_error(failed);
  std::vector<std::vector<SideEdge>> out(middles.size());
  for (TopExp_Explorer it(section.Shape(), TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    TopoDS_Shape face, plane;
    if (!section.HasAncestorFaceOn1(edge, face) || !section.HasAncestorFaceOn2(edge, plane)) continue;
    size_t stretch = 0;
    while (stretch < plane_faces.size() && !plane_faces[stretch].IsSame(plane)) ++stretch;
    if (stretch == plane_faces.size()) continue;
    SideEdge e;
    for (gp_Pnt p : edge_samples(edge)) {
      p.Translate(-s.sweep * middles[stretch]);
      e.points.push_back({p.X(), p.Y(), p.Z()});
    }
    for (size_t k = 0; k < s.faces.size() && e.face == 0; ++k) {
      if (!s.faces[k].IsNull() && s.faces[k].IsSame(face)) e.face = static_cast<int>(k) + 1;
    }
    out[stretch].push_back(e);
  }
  return out;
}

bool holds_one_solid(const TopoDS_Shape& shape) {
  const int solids = count_of(shape, TopAbs_SOLID);
  if (solids == 1) return true;
  return solids == 0 && count_of(shape, TopAbs_SHELL) >= 1 && count_of(shape, TopAbs_FACE) > 1;
}

SweptSolid swept_solid_from_shape(const TopoDS_Shape& shape, const std::string& source) {
  SweptSolid out;
  out.source = source;
  try {
    if (shape.IsNull()) throw InputError("the file holds no shape");
    TopTools_IndexedMapOfShape numbers;
    TopExp::MapShapes(shape, TopAbs_FACE, numbers);
    // Numbers OpenCASCADE's algorithms would loop on (the solid classifier, properties) first.
    for (int k = 1; k <= numbers.Extent(); ++k) {
      try {
        check_finite_geometry(TopoDS::Face(numbers(k)));
      } catch (const InputError& e) {
        throw InputError(face_name(k) + ": " + e.what());
      }
    }
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    if (box.IsVoid()) throw InputError("the file holds no solid");
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    const double size = std::sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0) + (z1 - z0) * (z1 - z0));
    double tolerance = 1e-7 * size;
    for (TopExp_Explorer it(shape, TopAbs_VERTEX); it.More(); it.Next()) {
      tolerance = std::max(tolerance, 2.0 * BRep_Tool::Tolerance(TopoDS::Vertex(it.Current())));
    }
    out.solid = the_solid(shape, numbers, tolerance);
    out.splines = has_splines(out.solid);
    out.faces.resize(static_cast<size_t>(numbers.Extent()));

    std::vector<CapFace> planar;
    std::vector<CylinderFace> cylinders;
    for (TopExp_Explorer it(out.solid, TopAbs_FACE); it.More(); it.Next()) {
      const TopoDS_Face face = TopoDS::Face(it.Current());
      const int number = numbers.FindIndex(face);
      if (number == 0) throw std::logic_error("swept solid: a face of the solid is not in the shape's face map");
      out.faces[static_cast<size_t>(number - 1)] = face;
      gp_Dir normal;
      if (planar_face_normal(face, &normal)) {
        planar.push_back(cap_face(face, number, normal, out.splines));
        continue;
      }
      // A cylinder can be a side face (an extruded arc, a drilled hole), if it runs along the sweep.
      // (A B-spline surface that is a cylinder too: edge_curve.h, face_cylinder.)
      gp_Cylinder cylinder;
      if (!face_cylinder(face, &cylinder)) {
        throw InputError(face_name(number) + " is curved (" + with_article(surface_name(face)) +
                         "): a swept solid's faces are planar, or cylinders along the sweep");
      }
      cylinders.push_back({number, cylinder.Axis().Direction()});
    }
    std::sort(planar.begin(), planar.end(), [](const CapFace& a, const CapFace& b) { return a.number < b.number; });

    GProp_GProps volume;
    volume_properties(out.solid, out.splines, volume);
    out.volume = volume.Mass();
    GProp_GProps area;
    surface_properties(out.solid, out.splines, area);
    out.area = area.Mass();

    std::optional<CapTrial> best, failed;
    auto key = [](const CapTrial& t) {
      return std::make_tuple(t.bottom->vertices.size(), t.bottom->area, -t.bottom->number, -t.top->number);
    };
    for (size_t i = 0; i < planar.size(); ++i) {
      for (size_t j = i + 1; j < planar.size(); ++j) {
        if (planar[i].normal.Dot(planar[j].normal) > -1.0 + 1e-12) continue;
        const CapTrial t = try_caps(planar[i], planar[j], planar, cylinders, out.faces, out.volume, tolerance);
        if (t.stage == 4) {
          if (!best || key(t) > key(*best)) best = t;
        } else if (!failed || std::make_pair(t.stage, t.bottom->area + t.top->area) >
                                  std::make_pair(failed->stage, failed->bottom->area + failed->top->area)) {
          failed = t;
        }
      }
    }
    if (!best) {
      // (A split across the sweep that the layers cannot follow names the remedy already.)
      const std::string hint = failed && failed->stage == 3 ? "" : refine_hint(out.solid, numbers.Extent());
      if (failed) throw InputError(failed->why + hint);
      throw InputError("no two faces are parallel and opposite: a swept solid has two parallel caps" + hint);
    }
    out.bottom = best->bottom->number;
    out.top = best->top->number;
    out.sweep = best->sweep;
    out.splits = best->splits;
    if (!out.splits.empty()) {
      // OpenCASCADE's section of the sides (side_edges_by_stretch) may never end on an invalid solid (a
      // face's curve run a billion times round its circle): its checker first. (Here, so that the
      // reading process meets it first too.)
      if (!occt_shape_valid(out.solid)) {
        throw InputError("its sides are split across the sweep, and OpenCASCADE's checker finds the solid invalid (a "
                         "face or an edge off its neighbours' geometry): repair the shape first (FreeCAD: Part > Check "
                         "geometry) or merge the split faces (Part > Create a copy > Refine shape)");
      }
    }
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  } catch (const Standard_Failure& e) {
    throw InputError(source + ": OpenCASCADE cannot evaluate the solid (" + e.DynamicType()->Name() + ": " +
                     e.GetMessageString() + ")");
  }
  out.cap = input_face_from_occt(out.faces[static_cast<size_t>(out.bottom - 1)],
                                 source + " (Face" + std::to_string(out.bottom) + ", a cap of the solid)");
  return out;
}

}  // namespace autoblock
