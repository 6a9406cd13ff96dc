// Faces with circular arcs through the mesh pipeline (issue 13): read as their chords, decomposed by
// the general engine, cut by OpenCASCADE on the true face, meshed with every boundary node on its arc.
#include <catch2/catch.hpp>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <TopoDS.hxx>


#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <cstdlib>
#include <random>
#include <string>

#include "core/api/face_meshing.h"
#include "core/data/arc_generator.h"
#include "core/geometry/circular_arc.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/io/input_face.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/mesh/mesh_quality.h"
#include "core/mesh/mesh_smoothing.h"
#include "core/region/region_policy.h"

using namespace autoblock;

namespace {

struct ArcMesh {
  InputFace face;
  MeshResult mesh;
};

// The face decomposed by the general engine's greedy policy with the mesh preset (deterministic) and
// meshed at size h (0: the face's longer side / 15).
ArcMesh mesh_arc_face(const TopoDS_Face& occt, const std::string& name, double h = 0.0) {
  ArcMesh out{input_face_from_occt(occt, name), {}};
  REQUIRE(out.face.is_general());
  RegionGreedyPolicy greedy;
  RegionEpisodeOptions episode;
  episode.reward = RewardPreset::Mesh;
  const RegionDecomposition d = decompose_region(out.face.region, greedy, episode);
  REQUIRE(d.complete());
  MeshOptions options;
  options.size = h > 0 ? h : out.face.region.bbox().longer_side() / 15.0;
  options.general = episode;
  out.mesh = mesh_region_decomposition(out.face, d, options);
  return out;
}

// The mesh's boundary nodes near an arc (on its polygon), and how far the farthest lies off the arc.
struct OnArcs {
  int nodes = 0;
  double worst = 0.0;  // relative to the radius
};
OnArcs boundary_nodes_on_arcs(const ArcMesh& m) {
  OnArcs result;
  std::vector<char> boundary(m.mesh.mesh.nodes.size(), 0);
  for (const MeshEdge& e : mesh_edges(m.mesh.mesh)) {
    if (e.uses == 1) boundary[static_cast<size_t>(e.a)] = boundary[static_cast<size_t>(e.b)] = 1;
  }
  for (size_t v = 0; v < boundary.size(); ++v) {
    if (!boundary[v]) continue;
    const Point2 p = m.mesh.mesh.nodes[v];
    const int arc = m.face.arcs.arc_of_point(p);
    if (arc < 0) continue;
    const CircularArc& a = m.face.arcs.arcs[static_cast<size_t>(arc)];
    ++result.nodes;
    result.worst = std::max(result.worst, std::fabs(std::hypot(p.x - a.center.x, p.y - a.center.y) - a.radius) / a.radius);
  }
  return result;
}

// The checks every face with arcs must pass: conformal, no inverted quad, the face's true area (the
// check's, from the arcs, against OpenCASCADE's), the quads' area plus the gap to the arcs equal to
// it, OpenCASCADE's blocks covering the face, and every boundary node near an arc on it.
void check_arc_mesh(const ArcMesh& m, const TopoDS_Face& occt) {
  const Conformity& c = m.mesh.conformity;
  INFO(c.problem);
  CHECK(c.conformal);
  CHECK(c.inverted_quads == 0);
  CHECK(c.face_area == Approx(occt_area(occt)).epsilon(1e-6));
  CHECK(c.quad_area + c.curved_gap_area == Approx(occt_area(occt)).epsilon(1e-6));
  CHECK(c.curved_gap_area != 0.0);
  CHECK(occt_area(m.mesh.model.compound) == Approx(occt_area(occt)).epsilon(1e-6));
  CHECK(occt_shape_valid(m.mesh.model.compound));
  const OnArcs on = boundary_nodes_on_arcs(m);
  CHECK(on.nodes > 0);
  CHECK(on.worst < 1e-9);
}

}  // namespace

TEST_CASE("arc faces: a plate with a round hole is read as chords and its arc", "[mesh][arc][occt]") {
  const TopoDS_Face plate = plate_with_holes(10, 6, {{5, 3, 1.5}});
  const InputFace face = input_face_from_occt(plate, "plate");
  REQUIRE(face.is_general());
  REQUIRE(face.arcs.arcs.size() == 1);
  const CircularArc& hole = face.arcs.arcs[0];
  CHECK(hole.center.x == Approx(5.0));
  CHECK(hole.center.y == Approx(3.0));
  CHECK(hole.radius == Approx(1.5));
  CHECK(std::fabs(hole.sweep) == Approx(2 * M_PI));
  REQUIRE(face.region.holes().size() == 1);
  CHECK(face.region.holes()[0].size() == 24);
  // The face lies outside the hole's circle: its polygon is circumscribed (tangents meeting at
  // r / cos 7.5 degrees), so the engine's polygon lies inside the true face.
  CHECK(hole.outside);
  for (const Point2& p : face.region.holes()[0]) CHECK(std::hypot(p.x - 5, p.y - 3) == Approx(1.5 / std::cos(M_PI / 24)).epsilon(1e-6));
  CHECK(face.region.area() < occt_area(plate));
  // A rounded rectangle's fillets are inscribed (chords): its polygon lies inside it too.
  const TopoDS_Face rounded = filleted_polygon(RectilinearPolygon{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}}, 1.5);
  const InputFace convex = input_face_from_occt(rounded, "rounded");
  REQUIRE(convex.arcs.arcs.size() == 4);
  for (const CircularArc& arc : convex.arcs.arcs) CHECK_FALSE(arc.outside);
  CHECK(convex.region.area() < occt_area(rounded));
  CHECK(convex.region.outer().size() == 4 * 7);
}

TEST_CASE("arc faces: a plate whose every curve is a B-spline meshes as the plate with round holes", "[mesh][arc][occt]") {
  // As some STEP translators write every curve: the holes' circles and the sides as B-splines
  // (edge_curve.h reads them as circles and lines), cut by OpenCASCADE on its twin made of a plane,
  // lines and circles (face_from_rings).
  const TopoDS_Face plate = plate_with_holes(12, 8, {{3.5, 4, 1.5}, {8.5, 4, 1.0}});
  const TopoDS_Face nurbs = TopoDS::Face(BRepBuilderAPI_NurbsConvert(plate, true).Shape());
  const ArcMesh m = mesh_arc_face(nurbs, "NURBS plate");
  // (Against the plate as made: OpenCASCADE's area of the spline surface is 0.1 % off.)
  check_arc_mesh(m, plate);
  const ArcMesh reference = mesh_arc_face(plate, "plate");
  CHECK(m.mesh.mesh.quads.size() == reference.mesh.mesh.quads.size());
  CHECK(m.mesh.quality.min_scaled_jacobian == Approx(reference.mesh.quality.min_scaled_jacobian).epsilon(1e-6));
}

TEST_CASE("arc faces: a disk meshes at the sizes where GLPK's integer presolve called it infeasible", "[mesh][arc]") {
  // The disk's five blocks have integer interval counts at every size, but at a radius of 2 and size
  // 0.2 (the default: a twentieth of the diameter), and at others, GLPK's integer presolve reported no
  // solution; the program is then solved again from the simplex's relaxation without it.
  for (const auto& [r, h] : std::vector<std::pair<double, double>>{{2.0, 0.2}, {10.0, 1.0}, {14.0, 1.4}, {2.0, 0.19}}) {
    INFO("radius " << r << ", size " << h);
    const TopoDS_Face face = disk(0, 0, r);
    const ArcMesh m = mesh_arc_face(face, "disk", h);
    check_arc_mesh(m, face);
  }
}

TEST_CASE("arc faces: a circular segment's 30-degree tips are meshed again with finer arc edges", "[mesh][arc][occt]") {
  // The arc from (5, 8.66) over (0, 10) to (-5, 8.66) on the circle of radius 10 about the origin, closed
  // by its chord: the tangent meets the chord at 30 degrees at each end (the face's bound: sin 30). A
  // quad at a tip has the angle of the chord to the arc's first node, smaller than the tangent's by
  // half that edge's turn: at the default size 26 degrees (0.44). The arc's edges from the tips are
  // made fine enough to keep 0.97 of the tip's sine, and that mesh is kept.
  const double s = 10.0 * std::sqrt(3.0) / 2.0;
  const gp_Pnt a(5.0, s, 0.0), top(0.0, 10.0, 0.0), b(-5.0, s, 0.0);
  const TopoDS_Edge arc = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(a, top, b).Value());
  const TopoDS_Edge chord = BRepBuilderAPI_MakeEdge(b, a);
  const TopoDS_Face occt = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(arc, chord).Wire());
  const ArcMesh m = mesh_arc_face(occt, "segment");
  check_arc_mesh(m, occt);
  CHECK(m.mesh.bound == Approx(0.5).epsilon(1e-3));
  CHECK(m.mesh.acute_tips);
  CHECK(m.mesh.quality.min_scaled_jacobian >= 0.97 * 0.5 - 1e-3);
}

// The face between two arcs over the chord from (0, 0) to (chord, 0), through (chord / 2, upper) and
// (chord / 2, lower), meshed with the search's blocks at the default size (the greedy policy's one
// template meets acute tips badly); its tips' angle `tip`: conformal, the bound sin tip, the tip pass
// kept and at least `fraction` of the bound, no quad past the smoothing's edge ratio.
namespace {
FaceMeshing checked_tip_mesh(double chord, double upper, double lower, double tip, const std::string& name,
                             double fraction = 0.97) {
  const gp_Pnt p(0.0, 0.0, 0.0), q(chord, 0.0, 0.0);
  const TopoDS_Edge top = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(q, gp_Pnt(0.5 * chord, upper, 0.0), p).Value());
  const TopoDS_Edge bottom = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(p, gp_Pnt(0.5 * chord, lower, 0.0), q).Value());
  const InputFace face = input_face_from_occt(BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(top, bottom).Wire()), name);
  REQUIRE(face.is_general());
  DecomposeSettings settings;
  settings.policy = "search";
  FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
  CHECK(m.result.conformity.conformal);
  CHECK(m.result.bound == Approx(std::sin(tip)).epsilon(1e-3));
  CHECK(m.result.acute_tips);
  CHECK(m.result.quality.min_scaled_jacobian >= fraction * std::sin(tip));
  CHECK(m.result.quality.max_aspect_ratio <= kSmoothingEdgeRatio * (1 + 1e-9));
  return m;
}
}  // namespace

TEST_CASE("arc faces: a lens's tips, where two arcs meet at 24 degrees, share the finer edges", "[mesh][arc][occt]") {
  // Two arcs through (0, 0) and (7, 0), each at 12 degrees to the chord there: tips of 24 degrees
  // (the bound sin 24), both sides arcs. The tip quad loses half of each first edge's turn, so each
  // arc's edges from the tip get half of what the tip allows; the mesh made so is judged conformal
  // (its edges near a tip lie in the other arc's polygon band too, FaceArcs::arc_of_mesh_edge) and
  // kept. (With the whole loss asked of each arc, as if the other side were straight: 0.961.)
  const double half = 12.0 * M_PI / 180.0, sag = 3.5 / std::sin(half) * (1.0 - std::cos(half));
  checked_tip_mesh(7.0, sag, -sag, 2.0 * half, "lens");
}

TEST_CASE("arc faces: a crescent's 24-degree tips get arc edges graded from them", "[mesh][arc][occt]") {
  // Two arcs bowing the same way over one chord: radius 7.9375 over 55 degrees above, radius 65.88
  // (6.4 degrees) below it, meeting at 24.3-degree tips (the shape of two real faces of 11752.stp).
  // Uniformly finer arc edges skew the quads where the fine side meets coarse ones (0.935 of the
  // bound, the first mesh kept); edges graded from the tips keep the tip quads within 0.95 of the
  // tip's sine with a few more quads only. (0.994 while the smoothing could draw the tip's quads into
  // slivers, an edge ratio of 1 446: kSmoothingEdgeRatio.)
  const double r2 = 7.9375, sweep2 = 54.94 * M_PI / 180.0, chord = 2.0 * r2 * std::sin(0.5 * sweep2);
  const double r1 = 65.88125, sweep1 = 2.0 * std::asin(0.5 * chord / r1);
  const FaceMeshing m = checked_tip_mesh(chord, r2 * (1.0 - std::cos(0.5 * sweep2)), r1 * (1.0 - std::cos(0.5 * sweep1)),
                                         0.5 * (sweep2 - sweep1), "crescent", 0.95);
  CHECK(m.result.mesh.quads.size() < 300u);
}

TEST_CASE("arc faces: an arc shorter than the default element size is one chord, its nodes still on it",
          "[mesh][arc][occt]") {
  // A 20 x 12 plate (default element size 1) with an L step: the outer corner (20, 0) filleted with
  // radius 0.3 (a quarter arc 0.47 long: one chord, a chamfer to the engine), the step's reflex corner
  // (8, 6) with radius 0.5 (0.79 long: one chord, circumscribed, the sharp corner to the engine), the
  // corner (0, 12) with radius 3 (4.7 long: samples every 15 degrees).
  const RectilinearPolygon l{{{0, 0}, {20, 0}, {20, 6}, {8, 6}, {8, 12}, {0, 12}}, {}};
  std::vector<double> radii(6, 0.0);
  radii[1] = 0.3;
  radii[3] = 0.5;
  radii[5] = 3.0;
  const TopoDS_Face occt = filleted_polygon(l, radii);
  const InputFace face = input_face_from_occt(occt, "stepped plate");
  REQUIRE(face.arcs.arcs.size() == 3);
  int short_arcs = 0;
  for (const CircularArc& arc : face.arcs.arcs) {
    const bool small = arc.radius < 1.0;
    CHECK(arc.chords == (small ? 1 : 0));
    CHECK(arc_chord_count(arc) == (small ? 1 : 6));
    CHECK(polygonise_arc(arc).size() == (small ? (arc.outside ? 3u : 2u) : 7u));
    short_arcs += small;
  }
  CHECK(short_arcs == 2);
  // Three plain corners, the small convex fillet's two ends, the small concave one's two ends and sharp
  // corner between them, the large fillet's 7 samples.
  CHECK(face.region.outer().size() == 3 + 2 + 3 + 7);
  // Its mesh: conformal, the quads' area and the gap to the arcs the face's, every boundary node near
  // an arc on it; the short arcs take one interval or more, as their length asks, not one per sample.
  const ArcMesh m = mesh_arc_face(occt, "stepped plate", 1.0);
  check_arc_mesh(m, occt);
}

TEST_CASE("arc faces: plates with holes, fillets and a slot mesh conformally with nodes on the arcs",
          "[mesh][arc]") {
  const struct {
    TopoDS_Face face;
    const char* name;
  } faces[] = {
      {plate_with_holes(10, 6, {{5, 3, 1.5}}), "plate with a hole"},
      {plate_with_holes(20, 10, {{4, 3, 1}, {10, 6, 1.5}, {16, 4, 2}}), "plate with three holes"},
      {filleted_polygon(RectilinearPolygon{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}}, 1.5), "rounded rectangle"},
      {filleted_polygon(RectilinearPolygon{{{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}}, {}}, 1.0), "filleted L"},
      {slotted_plate(), "slotted plate"},
      {disk(1, 2, 3), "disk"},
  };
  for (const auto& f : faces) {
    INFO(f.name);
    const ArcMesh m = mesh_arc_face(f.face, f.name);
    check_arc_mesh(m, f.face);
  }
}

TEST_CASE("arc faces: the gap between the quads and the arcs shrinks with the element size", "[mesh][arc]") {
  // Chords of length c on a circle of radius r leave c^3 / (12 r) each: once every model edge along
  // the arc carries several intervals, a quarter of the size leaves about a sixteenth of the gap.
  const TopoDS_Face plate = plate_with_holes(10, 6, {{5, 3, 1.5}});
  const ArcMesh coarse = mesh_arc_face(plate, "coarse", 0.2), fine = mesh_arc_face(plate, "fine", 0.05);
  const double ratio = fine.mesh.conformity.curved_gap_area / coarse.mesh.conformity.curved_gap_area;
  INFO("gaps " << coarse.mesh.conformity.curved_gap_area << " " << fine.mesh.conformity.curved_gap_area);
  CHECK(ratio > 0.0);
  CHECK(ratio < 0.25);
  // A hole: the quads cover part of it (their chords cut across the circle), so the gap is negative.
  CHECK(coarse.mesh.conformity.curved_gap_area < 0);
  check_arc_mesh(fine, plate);
}

namespace {

// The generated faces of the property test below (seed 20261201, scales 37 and 1 in turn) all mesh:
// 36 and 37 since the O-grid and the arcs' merged edges; filleted union 22, whose reflex fillets left
// slivers, since the concave runs of block.h; rounded plate 56 ("an edge is used by more than two
// pieces": two cuts meeting at 15 degrees, their meeting point rounded 5 quanta apart in the parts on
// either side) since block_model merges vertices up to twice its tolerance.

// Inputs: count, the faces to mesh. Output: how many of them meshed conformally, and how many were
//         checked. The faces are random_arc_face's from seed 20261201, scales 37 and 1 in turn.
std::pair<int, int> mesh_generated_arc_faces(int count) {
  std::mt19937_64 rng(20261201);
  int faces = 0, checked = 0;
  for (int i = 0; i < count; ++i) {
    const ArcFace f = random_arc_face(rng, i % 2 ? 1.0 : 37.0);
    ++checked;
    INFO("face " << i << ": " << f.name);
    REQUIRE(occt_shape_valid(f.face));
    const ArcMesh m = mesh_arc_face(f.face, f.name);
    check_arc_mesh(m, f.face);
    faces += m.mesh.conformity.conformal;
  }
  return {faces, checked};
}

}  // namespace

TEST_CASE("arc faces: generated plates, fillets and slots all mesh conformally", "[mesh][arc][property]") {
  const int count = std::getenv("AUTOBLOCK_ARC_FACES") ? std::atoi(std::getenv("AUTOBLOCK_ARC_FACES")) : 60;
  const auto [faces, checked] = mesh_generated_arc_faces(count);
  CHECK(faces == checked);
}

