#include "core/data/arc_generator.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepFilletAPI_MakeFillet2d.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "core/common/error.h"
#include "core/data/general_generator.h"
#include "core/data/shape_generator.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/io/input_face.h"

namespace autoblock {
namespace {

TopoDS_Face first_face(const TopoDS_Shape& shape) {
  TopExp_Explorer faces(shape, TopAbs_FACE);
  if (!faces.More()) throw std::runtime_error("arc generator: no face");
  return TopoDS::Face(faces.Current());
}

// The face less the solid (a prism through z = 0).
TopoDS_Face cut(const TopoDS_Face& face, const TopoDS_Shape& tool) {
  BRepAlgoAPI_Cut op(face, tool);
  if (!op.IsDone()) throw std::runtime_error("arc generator: the cut failed");
  return first_face(op.Shape());
}

TopoDS_Shape cylinder(double x, double y, double r) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp_Dir(0, 0, 1)), r, 2).Shape();
}

TopoDS_Face plate(double w, double h) {
  return BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0, w, 0, h).Face();
}

double uniform(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
int uniform_int(std::mt19937_64& rng, int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }
bool chance(std::mt19937_64& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }

// Fillet radii for a ring's corners: each corner taken with probability share (all of them when share
// is 1; at least one unless every corner is nearly straight), its tangent length a random fraction of 0.45 of the shorter edge there (so two
// fillets never meet on an edge), the radius the one that tangent length gives at the corner's turn.
std::vector<double> fillet_radii(std::mt19937_64& rng, const Ring& ring, double share) {
  const size_t n = ring.size();
  std::vector<double> radii(n, 0.0);
  bool any = false;
  for (size_t i = 0; i < n; ++i) {
    const Point2 p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
    const double lp = std::hypot(v.x - p.x, v.y - p.y), lq = std::hypot(q.x - v.x, q.y - v.y);
    const double cosine = ((v.x - p.x) * (q.x - v.x) + (v.y - p.y) * (q.y - v.y)) / (lp * lq);
    const double turn = std::acos(std::clamp(cosine, -1.0, 1.0));
    if (turn < 5.0 * M_PI / 180.0 || !chance(rng, share)) continue;
    const double tangent = uniform(rng, 0.15, 1.0) * 0.45 * std::min(lp, lq);
    radii[i] = tangent / std::tan(0.5 * turn);
    any = true;
  }
  if (!any && share < 1.0) return fillet_radii(rng, ring, 1.0);
  return radii;
}

// Up to count holes in the plate [0, w] x [0, h]: radii varied (0.1 to 1 of a largest radius that
// shrinks with the count), each at least margin from the sides, from the other holes and from the
// places allowed() refuses. Fewer when they do not fit.
std::vector<RoundHole> place_holes(std::mt19937_64& rng, double w, double h, int count,
                                   const std::function<bool(const RoundHole&, double margin)>& allowed) {
  const double side = std::min(w, h);
  const double largest = side * (count == 1 ? 0.32 : count == 2 ? 0.24 : 0.18);
  std::vector<RoundHole> holes;
  for (int k = 0; k < count; ++k) {
    for (int attempt = 0; attempt < 200; ++attempt) {
      const double r = largest * std::pow(10.0, uniform(rng, -1.0, 0.0));
      const double margin = std::max(0.04 * side, 0.25 * r);
      if (2.0 * (r + margin) >= side) continue;
      const RoundHole hole{uniform(rng, r + margin, w - r - margin), uniform(rng, r + margin, h - r - margin), r};
      bool ok = allowed(hole, margin);
      for (const RoundHole& other : holes) {
        const double gap = std::max(margin, std::max(0.04 * side, 0.25 * other.r));
        ok = ok && std::hypot(hole.x - other.x, hole.y - other.y) >= hole.r + other.r + gap;
      }
      if (ok) {
        holes.push_back(hole);
        break;
      }
    }
  }
  return holes;
}

std::vector<RoundHole> place_holes(std::mt19937_64& rng, double w, double h, int count) {
  return place_holes(rng, w, h, count, [](const RoundHole&, double) { return true; });
}

// The holes (inner wires) and circular edges of a face.
void count_features(ArcFace* f) {
  int wires = 0;
  for (TopExp_Explorer w(f->face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  f->holes = std::max(0, wires - 1);
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(f->face, TopAbs_EDGE, edges);
  f->arcs = 0;
  for (int e = 1; e <= edges.Extent(); ++e) f->arcs += BRepAdaptor_Curve(TopoDS::Edge(edges(e))).GetType() == GeomAbs_Circle;
}

// True when OpenCASCADE's checker passes the face and AutoBlock's reader takes it with its arcs.
bool accepted(const TopoDS_Face& face) {
  if (!occt_shape_valid(face)) return false;
  try {
    return !input_face_from_occt(face, "generated").arcs.empty();
  } catch (const InputError&) {
    return false;
  }
}

std::string holes_phrase(size_t n) { return std::to_string(n) + (n == 1 ? " hole" : " holes"); }

// One draw of the kind; may throw (a fillet or a cut that fails) or leave the face null.
ArcFace draw(std::mt19937_64& rng, ArcKind kind, double scale) {
  ArcFace f;
  f.kind = kind;
  const double w = scale * uniform(rng, 6, 24), h = scale * uniform(rng, 4, 14);
  switch (kind) {
    case ArcKind::FilletedUnion: {
      GeneratorOptions options;
      options.min_rects = 2;
      options.max_rects = 6;
      const GeneratedShape u = generate_shape(rng, options);
      Ring outer;
      for (const Point2& p : u.polygon.outer) outer.push_back({scale * p.x, scale * p.y});
      const std::vector<double> radii = fillet_radii(rng, outer, chance(rng, 0.4) ? 1.0 : uniform(rng, 0.3, 0.8));
      f.face = filleted_polygon(RectilinearPolygon{outer, {}}, radii);
      f.name = "filleted union of " + std::to_string(u.rectangles) + " rectangles";
      break;
    }
    case ArcKind::PlateHoles: {
      const std::vector<RoundHole> holes = place_holes(rng, w, h, uniform_int(rng, 1, 4));
      f.face = plate_with_holes(w, h, holes);
      f.name = "plate with " + holes_phrase(holes.size());
      break;
    }
    case ArcKind::SlottedPlate: {
      const double side = std::min(w, h), margin = 0.05 * side;
      Slot slot;
      slot.r = side * uniform(rng, 0.05, 0.2);
      slot.angle = chance(rng, 0.25) ? uniform_int(rng, 0, 1) * 0.5 * M_PI : uniform(rng, 0.0, M_PI);
      slot.length = slot.r * uniform(rng, 0.5, 8.0);
      // Shortened until the stadium fits with the margin.
      double ex = 0, ey = 0;
      for (;;) {
        ex = 0.5 * slot.length * std::fabs(std::cos(slot.angle)) + slot.r + margin;
        ey = 0.5 * slot.length * std::fabs(std::sin(slot.angle)) + slot.r + margin;
        if (2 * ex < w && 2 * ey < h) break;
        slot.length *= 0.8;
        if (slot.length < 0.2 * slot.r) return f;
      }
      slot.centre = {uniform(rng, ex, w - ex), uniform(rng, ey, h - ey)};
      f.face = slotted_plate(w, h, slot);
      f.name = "plate with a slot";
      break;
    }
    case ArcKind::RoundedPolygon: {
      GeneralOptions options;
      options.kind = GeneralKind::Polygon;
      options.min_vertices = 5;
      options.max_vertices = 12;
      options.size = 10.0 * scale;
      const GeneralShape shape = generate_general_shape(rng, options);
      const std::vector<double> radii = fillet_radii(rng, shape.outer, chance(rng, 0.4) ? 1.0 : uniform(rng, 0.3, 0.8));
      f.face = filleted_polygon(RectilinearPolygon{shape.outer, {}}, radii);
      f.name = "polygon of " + std::to_string(shape.outer.size()) + " vertices with rounded corners";
      break;
    }
    case ArcKind::RoundedPlateHoles: {
      const double rf = std::min(w, h) * uniform(rng, 0.05, 0.3);
      std::vector<double> radii(4, 0.0);
      for (double& r : radii) r = chance(rng, 0.75) ? rf : 0.0;
      if (radii == std::vector<double>(4, 0.0)) radii[static_cast<size_t>(uniform_int(rng, 0, 3))] = rf;
      // Holes stay out of the squares of side rf (plus the margin) at the corners.
      const auto away = [&](const RoundHole& hole, double margin) {
        const double reach = rf + hole.r + margin;
        const bool near_x = hole.x < reach || hole.x > w - reach, near_y = hole.y < reach || hole.y > h - reach;
        return !(near_x && near_y);
      };
      const std::vector<RoundHole> holes = place_holes(rng, w, h, uniform_int(rng, 1, 3), away);
      if (holes.empty()) return f;
      const Ring rectangle{{0, 0}, {w, 0}, {w, h}, {0, h}};
      f.face = cut_round_holes(filleted_polygon(RectilinearPolygon{rectangle, {}}, radii), holes);
      f.name = "rounded plate with " + holes_phrase(holes.size());
      break;
    }
  }
  return f;
}

}  // namespace

TopoDS_Face cut_round_holes(const TopoDS_Face& face, const std::vector<RoundHole>& holes) {
  TopoDS_Face out = face;
  for (const RoundHole& hole : holes) out = cut(out, cylinder(hole.x, hole.y, hole.r));
  return out;
}

TopoDS_Face plate_with_holes(double w, double h, const std::vector<RoundHole>& holes) {
  return cut_round_holes(plate(w, h), holes);
}

TopoDS_Face filleted_polygon(const RectilinearPolygon& polygon, const std::vector<double>& radii) {
  const TopoDS_Face face = occt_face_from_polygon(polygon, 0.0, true);
  BRepFilletAPI_MakeFillet2d fillet(face);
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
  double extent = 0.0;
  for (const Point2& p : polygon.outer) extent = std::max({extent, std::fabs(p.x), std::fabs(p.y)});
  // The outer ring's corners by position (the face's vertices include the holes').
  for (size_t k = 0; k < polygon.outer.size() && k < radii.size(); ++k) {
    if (!(radii[k] > 0.0)) continue;
    const Point2 p = polygon.outer[k];
    for (int v = 1; v <= vertices.Extent(); ++v) {
      const gp_Pnt at = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
      if (std::hypot(at.X() - p.x, at.Y() - p.y) > 1e-9 * std::max(1.0, extent)) continue;
      fillet.AddFillet(TopoDS::Vertex(vertices(v)), radii[k]);
      if (fillet.Status() != ChFi2d_IsDone) throw std::runtime_error("arc generator: the fillet failed");
    }
  }
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("arc generator: the fillet failed");
  return first_face(fillet.Shape());
}

TopoDS_Face filleted_polygon(const RectilinearPolygon& polygon, double radius, const std::vector<int>& corners) {
  std::vector<double> radii(polygon.outer.size(), corners.empty() ? radius : 0.0);
  for (int k : corners) radii.at(static_cast<size_t>(k)) = radius;
  return filleted_polygon(polygon, radii);
}

TopoDS_Face slotted_plate(double w, double h, const Slot& slot) {
  const double c = std::cos(slot.angle), s = std::sin(slot.angle), half = 0.5 * slot.length, r = slot.r;
  auto at = [&](double along, double across) {
    return gp_Pnt(slot.centre.x + along * c - across * s, slot.centre.y + along * s + across * c, 0);
  };
  const gp_Pnt a = at(-half, -r), b = at(half, -r), d = at(half, r), e = at(-half, r);
  const TopoDS_Edge bottom = BRepBuilderAPI_MakeEdge(a, b).Edge();
  const TopoDS_Edge right = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(b, at(half + r, 0), d).Value()).Edge();
  const TopoDS_Edge top = BRepBuilderAPI_MakeEdge(d, e).Edge();
  const TopoDS_Edge left = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(e, at(-half - r, 0), a).Value()).Edge();
  const TopoDS_Wire wire = BRepBuilderAPI_MakeWire(bottom, right, top, left).Wire();
  const TopoDS_Face stadium = BRepBuilderAPI_MakeFace(wire).Face();
  const TopoDS_Shape tool = BRepPrimAPI_MakePrism(stadium, gp_Vec(0, 0, 2)).Shape();
  gp_Trsf down;
  down.SetTranslation(gp_Vec(0, 0, -1));
  return cut(plate(w, h), tool.Moved(TopLoc_Location(down)));
}

TopoDS_Face slotted_plate() { return slotted_plate(20, 10, Slot{{10, 5}, 8, 2, 0}); }

TopoDS_Face disk(double x, double y, double r) {
  const TopoDS_Edge circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(x, y, 0), gp_Dir(0, 0, 1)), r)).Edge();
  return BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(circle).Wire()).Face();
}

std::string arc_kind_name(ArcKind kind) {
  switch (kind) {
    case ArcKind::FilletedUnion: return "filleted-union";
    case ArcKind::PlateHoles: return "plate-holes";
    case ArcKind::SlottedPlate: return "slotted-plate";
    case ArcKind::RoundedPolygon: return "rounded-polygon";
    case ArcKind::RoundedPlateHoles: return "rounded-plate-holes";
  }
  return "plate-holes";
}

ArcFace random_arc_face(std::mt19937_64& rng, ArcKind kind, double scale) {
  for (int attempt = 0; attempt < 1000; ++attempt) {
    ArcFace f;
    try {
      f = draw(rng, kind, scale);
    } catch (const Standard_Failure&) {
      continue;
    } catch (const std::runtime_error&) {
      continue;
    }
    if (f.face.IsNull() || !accepted(f.face)) continue;
    count_features(&f);
    return f;
  }
  throw std::runtime_error("arc generator: no valid " + arc_kind_name(kind) + " face in 1000 draws");
}

ArcFace random_arc_face(std::mt19937_64& rng, double scale) {
  return random_arc_face(rng, static_cast<ArcKind>(uniform_int(rng, 0, kArcKinds - 1)), scale);
}

ArcFace generate_arc_face(std::mt19937_64& rng, const ArcOptions& options) {
  if (!(options.min_scale > 0.0) || !(options.max_scale >= options.min_scale) || !std::isfinite(options.max_scale)) {
    throw InputError("invalid arc face options (0 < min scale <= max scale)");
  }
  const double scale = std::exp(uniform(rng, std::log(options.min_scale), std::log(options.max_scale)));
  return random_arc_face(rng, scale);
}

}  // namespace autoblock
