// Faces in any plane, turned within their plane, and with edges at any angle, through core/api: the
// face's own frame (occt_face.h, face_frame) and the general engine behind decompose_input_face.
#include "support/catch_torch.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <TopoDS_Wire.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "core/api/face_actions.h"
#include "core/api/face_meshing.h"
#include "core/baselines/min_rectangles.h"
#include "core/common/error.h"
#include "core/data/arc_generator.h"
#include "core/data/general_generator.h"
#include "core/data/shape_generator.h"
#include "core/geometry/occt_face.h"
#include "core/region/block.h"
#include "core/geometry/occt_properties.h"
#include "core/io/decomposition_json.h"
#include "core/io/input_face.h"
#include "core/region/region_search.h"
#include "core/region/region_snapshot.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

TopoDS_Face moved(const TopoDS_Face& face, const gp_Trsf& move) {
  return TopoDS::Face(BRepBuilderAPI_Transform(face, move, true).Shape());
}

// A rotation about a skew axis through (5, -3, 2), then a shift: the face ends up in a tilted plane.
gp_Trsf tilt() {
  gp_Trsf rotation, shift;
  rotation.SetRotation(gp_Ax1(gp_Pnt(5, -3, 2), gp_Dir(1, 2, 3)), 0.7);
  shift.SetTranslation(gp_Vec(10, 20, -30));
  return shift * rotation;
}

gp_Trsf turn_about_z(double radians) {
  gp_Trsf t;
  t.SetRotation(gp_Ax1(gp_Pnt(1, 2, 0), gp_Dir(0, 0, 1)), radians);
  return t;
}

// The largest distance between the corners of two shapes' bounding boxes.
double box_distance(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  Bnd_Box ba, bb;
  BRepBndLib::Add(a, ba, false);
  BRepBndLib::Add(b, bb, false);
  return std::max(ba.CornerMin().Distance(bb.CornerMin()), ba.CornerMax().Distance(bb.CornerMax()));
}

TopoDS_Face general_face(std::uint64_t seed, GeneralKind kind, bool holes) {
  return occt_face_from_polygon(test::general_polygon(seed, kind, holes), 0.0, true);
}

// A face of tests/data/arcs (a general face, checked).
InputFace arc_test_face(const std::string& name) {
  InputFace face = load_input_face(std::string(AUTOBLOCK_SOURCE_DIR) + "/tests/data/arcs/" + name + ".brep");
  REQUIRE(face.is_general());
  return face;
}

// The search's settings without its time limit: the same searches on a loaded machine.
DecomposeSettings untimed_settings() {
  DecomposeSettings settings;
  settings.policy_settings.general_time_limit = 0.0;
  return settings;
}

// Inputs: name, a face of tests/data/arcs. Output: its mesh by `mesh`'s tries, untimed, checked
// complete and conformal.
FaceMeshing meshed_arc_face(const std::string& name) {
  FaceMeshing m = mesh_input_face(arc_test_face(name), untimed_settings(), MeshOptions{});
  REQUIRE(m.decomposition.region.complete());
  CHECK(m.result.conformity.conformal);
  return m;
}

}  // namespace

TEST_CASE("a rectilinear face in a tilted plane or turned in its plane gets its axis-aligned twin's blocks",
          "[api][frame]") {
  const TopoDS_Face flat = occt_face_from_polygon(test::polygon_of(test::l_shape()), 0.0, true);
  const InputFace twin = check_face(flat, "flat");
  REQUIRE(twin.frame.identity());
  DecomposeSettings settings;
  settings.policy = "optimal";
  const FaceDecomposition expected = decompose_input_face(twin, settings);
  for (const gp_Trsf& move : {tilt(), turn_about_z(0.5), turn_about_z(-1.2)}) {
    const TopoDS_Face model = moved(flat, move);
    const InputFace face = check_face(model, "moved");
    REQUIRE_FALSE(face.is_general());
    CHECK_FALSE(face.frame.identity());
    CHECK(polygon_area(face.planar.polygon) == Approx(polygon_area(twin.planar.polygon)).epsilon(1e-9));
    CHECK(min_rectangles(face.grid.whole) == min_rectangles(twin.grid.whole));
    const FaceDecomposition result = decompose_input_face(face, settings);
    CHECK(result.decomposition.blocks.size() == expected.decomposition.blocks.size());
    CHECK(result.decomposition.total_return == Approx(expected.decomposition.total_return).epsilon(1e-9));
    // The blocks come back where the face is in the model.
    CHECK(occt_area(result.shape) == Approx(occt_area(model)).epsilon(1e-9));
    CHECK(box_distance(result.shape, model) < 1e-6);
    CHECK(occt_shape_valid(result.shape));
  }
}

TEST_CASE("rectilinear faces turned by any angle get their twins' blocks and meshes", "[api][frame]") {
  // Unions of rectangles with holes, turned within their plane by angles from half a degree to 271: the
  // grid engine in the face's own frame gives the axis-aligned twin's blocks (count, areas, return),
  // and the mesh stays exact rectangles (scaled Jacobian 1, no irregular vertex). The quad count may
  // differ: a strip whose length lies half-way between two counts of h is a tie for interval
  // assignment, which the turn's rounding (within the face's tolerance) breaks either way.
  std::mt19937_64 rng(44);
  GeneratorOptions options;
  options.holes = true;
  options.max_rects = 6;
  int turned_faces = 0;
  for (int f = 0; f < 6; ++f) {
    const GeneratedShape shape = generate_shape(rng, options);
    const TopoDS_Face flat = occt_face_from_polygon(shape.polygon, 0.0, true);
    const InputFace twin = check_face(flat, "twin");
    DecomposeSettings settings;
    settings.policy = "greedy";
    const FaceMeshing reference = mesh_input_face(twin, settings, MeshOptions{});
    std::vector<double> twin_areas;
    for (const Box& b : reference.decomposition.decomposition.blocks) twin_areas.push_back(b.width() * b.height());
    std::sort(twin_areas.begin(), twin_areas.end());
    for (double degrees : {0.5, 17.0, 30.0, 45.0, 89.9, 90.0, 133.0, 271.0}) {
      INFO("face " << f << " turned by " << degrees << " degrees");
      const InputFace face = check_face(moved(flat, turn_about_z(degrees * M_PI / 180.0)), "turned");
      REQUIRE_FALSE(face.is_general());
      const FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
      const Decomposition& d = m.decomposition.decomposition;
      REQUIRE(d.complete());
      REQUIRE(d.blocks.size() == twin_areas.size());
      CHECK(d.total_return == Approx(reference.decomposition.decomposition.total_return).epsilon(1e-9));
      std::vector<double> areas;
      for (const Box& b : d.blocks) areas.push_back(b.width() * b.height());
      std::sort(areas.begin(), areas.end());
      for (size_t i = 0; i < areas.size(); ++i) CHECK(areas[i] == Approx(twin_areas[i]).epsilon(1e-9));
      CHECK(m.result.conformity.conformal);
      CHECK(m.result.quality.min_scaled_jacobian == Approx(1.0));
      CHECK(m.result.quality.irregular_interior_nodes == 0);
      ++turned_faces;
    }
  }
  CHECK(turned_faces == 48);
}

TEST_CASE("a face with edges at any angle goes to the general engine, and OpenCASCADE cuts its blocks", "[api][general]") {
  int faces = 0;
  for (const GeneralKind kind : {GeneralKind::Polygon, GeneralKind::Chamfered, GeneralKind::Turned}) {
    for (const bool holes : {false, true}) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const TopoDS_Face occt = general_face(seed * 7 + (holes ? 100 : 0), kind, holes);
        for (const bool tilted : {false, true}) {
          const TopoDS_Face model = tilted ? moved(occt, tilt()) : occt;
          const InputFace face = check_face(model, "general");
          INFO(general_kind_name(kind) << " holes " << holes << " seed " << seed << " tilted " << tilted);
          // A turned union of rectangles is rectilinear in its own frame: the grid engine takes it.
          CHECK(face.is_general() == (kind != GeneralKind::Turned));
          CHECK(face.frame.identity() == (!tilted && kind != GeneralKind::Turned));
          DecomposeSettings settings;
          settings.policy = "greedy";
          const FaceDecomposition result = decompose_input_face(face, settings);
          const size_t pieces = face.is_general() ? result.region.finished.size() : result.decomposition.blocks.size();
          CHECK((face.is_general() ? result.region.complete() : result.decomposition.complete()));
          CHECK(result.block_faces.size() == pieces);
          CHECK(occt_area(result.shape) == Approx(occt_area(model)).epsilon(1e-6));
          CHECK(box_distance(result.shape, model) < 1e-6 * 200);
          CHECK(occt_shape_valid(result.shape));
          ++faces;
        }
      }
    }
  }
  CHECK(faces == 36);
  // A face that is a block already (a parallelogram): no cut, one block, the face itself.
  const InputFace parallelogram = check_face(
      occt_face_from_polygon(RectilinearPolygon{{{0, 0}, {4, 0}, {5, 2}, {1, 2}}, {}}, 1.0, true), "parallelogram");
  REQUIRE(parallelogram.is_general());
  const FaceDecomposition one = decompose_input_face(parallelogram, DecomposeSettings{});
  CHECK(one.region.blocks == 1);
  CHECK(one.region.cuts.empty());
  REQUIRE(one.block_faces.size() == 1);
  CHECK(occt_area(one.shape) == Approx(8.0));
}

TEST_CASE("every face of a decomposition's conformal compound meshes on its own (flat vertices, snapped corners)",
          "[api][general][mesh]") {
  // A block of the compound has vertices where its neighbours' edges end (flat vertices), and a block
  // of a general face has corners snapped to the face's lattice, off its twin's grid by rounding.
  int meshed = 0, rectangles = 0;
  for (const GeneralKind kind : {GeneralKind::Polygon, GeneralKind::Chamfered, GeneralKind::Turned}) {
    const TopoDS_Face occt = general_face(11 + static_cast<int>(kind), kind, true);
    const FaceDecomposition d = decompose_input_face(check_face(occt, "face"), DecomposeSettings{});
    for (TopExp_Explorer it(d.shape, TopAbs_FACE); it.More(); it.Next()) {
      const InputFace block = check_face(TopoDS::Face(it.Current()), "block");
      INFO(general_kind_name(kind) << " block " << meshed);
      const FaceMeshing m = mesh_input_face(block, DecomposeSettings{}, MeshOptions{});
      CHECK(m.result.conformity.conformal);
      CHECK(m.result.mesh.quads.size() > 0);
      rectangles += block.is_general() ? 0 : 1;
      ++meshed;
    }
  }
  CHECK(meshed > 10);
  CHECK(rectangles > 0);  // the grid engine's path is exercised
}

TEST_CASE("a poor searched mesh is searched again (other widths, other block rules), and the best kept", "[api][general][mesh]") {
  // A generated hexagon whose mesh from the search of width 4 under the default rules stays below
  // kRetryBelow of its bound (0.76; other block rules reach 0.97); a width set in the settings makes
  // the first try.
  const RectilinearPolygon polygon{{{29.131113, 51.346410}, {-72.385620, 6.914996}, {-80.578092, -2.340715}, {-54.793450, -21.378219}, {21.978369, -96.415473}, {28.756321, -92.866493}}, {}};
  const InputFace face = check_face(occt_face_from_polygon(polygon, 0.0, true), "hexagon");
  REQUIRE(face.is_general());
  DecomposeSettings settings;
  settings.policy_settings.general_time_limit = 0.0;  // the same searches on a loaded machine
  settings.policy_settings.general_search_width = 4;
  settings.occt_blocks = false;
  settings.mesh_tries = false;  // the first try alone
  MeshOptions options;
  options.general.reward = RewardPreset::Mesh;
  const FaceDecomposition first = decompose_input_face(face, settings);
  const MeshResult first_mesh = mesh_region_decomposition(face, first.region, options);
  const double first_ratio = first_mesh.quality.min_scaled_jacobian / first_mesh.bound;
  INFO("first try: " << first_mesh.quality.min_scaled_jacobian << ", bound " << first_mesh.bound << ", topology bound " << first_mesh.topology_bound);
  REQUIRE(first_ratio < kRetryBelow);
  const FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
  // Another search, or the same blocks with finer edges (attempts counts the searches).
  CHECK((m.attempts >= 2 || m.min_edge_intervals > 1));
  CHECK(m.result.conformity.conformal);
  // What was kept differs from the first attempt: another width, other block rules or finer edges.
  CHECK((m.search_width != 4 || m.corner_fraction != kMeshCornerFraction || m.min_edge_intervals > 1));
  CHECK(m.result.quality.min_scaled_jacobian / m.result.bound > first_ratio);
  CHECK(face_meshing_json("hexagon", m)["attempts"] == m.attempts);
  // Without a width, the tries begin with kSearchTries' first; a good mesh is kept at the first try.
  settings.policy_settings.general_search_width = 0;
  const InputFace parallelogram = check_face(
      occt_face_from_polygon(RectilinearPolygon{{{0, 0}, {4, 0}, {5, 2}, {1, 2}}, {}}, 1.0, true), "parallelogram");
  const FaceMeshing once = mesh_input_face(parallelogram, settings, MeshOptions{});
  CHECK(once.attempts == 1);
  CHECK(once.search_width == kSearchTries[0].width);
  CHECK(once.corner_fraction == kSearchTries[0].corner_fraction);
  CHECK_FALSE(once.cut_smooth_parts);
  // Every try after the first is another search (no two alike); the last but one alone cuts smooth
  // parts, the last alone leaves tight cells' O-grids out.
  for (size_t i = 0; i < std::size(kSearchTries); ++i) {
    for (size_t j = i + 1; j < std::size(kSearchTries); ++j) {
      CHECK((kSearchTries[i].width != kSearchTries[j].width || kSearchTries[i].corner_fraction != kSearchTries[j].corner_fraction ||
             kSearchTries[i].cut_smooth_parts != kSearchTries[j].cut_smooth_parts ||
             kSearchTries[i].tight_ogrid != kSearchTries[j].tight_ogrid));
    }
    CHECK(kSearchTries[i].cut_smooth_parts == (i + 2 == std::size(kSearchTries)));
    CHECK(kSearchTries[i].tight_ogrid == (i + 1 != std::size(kSearchTries)));
  }
}

TEST_CASE("a face bounded by circles alone, in a tilted or an upright plane, gets its own frame and meshes",
          "[api][frame][arc]") {
  // A washer (radii 10 and 4) and a disk have no straight edge to set a frame by: they take their plane's.
  BRepAlgoAPI_Cut washer_cut(disk(0, 0, 10), disk(0, 0, 4));
  REQUIRE(washer_cut.IsDone());
  TopExp_Explorer washer_faces(washer_cut.Shape(), TopAbs_FACE);
  REQUIRE(washer_faces.More());
  const TopoDS_Face washer = TopoDS::Face(washer_faces.Current());
  gp_Trsf upright;
  upright.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), M_PI / 2);
  struct Case {
    TopoDS_Face face;
    double area;
    size_t arcs;
  };
  const std::vector<Case> cases{{washer, M_PI * (100 - 16), 2},
                                {moved(washer, tilt()), M_PI * (100 - 16), 2},
                                {moved(disk(1, 2, 3), upright), 9 * M_PI, 1},
                                {moved(disk(1, 2, 3), tilt()), 9 * M_PI, 1}};
  for (size_t k = 0; k < cases.size(); ++k) {
    CAPTURE(k);
    const InputFace face = check_face(cases[k].face, "round");
    CHECK(face.frame.identity() == (k == 0));
    REQUIRE(face.is_general());
    CHECK(face.arcs.arcs.size() == cases[k].arcs);
    DecomposeSettings settings;
    settings.policy_settings.general_time_limit = 0.0;
    const FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
    REQUIRE(m.result.conformity.conformal);
    // The quads and the gaps between their chords and the arcs make up the true face.
    CHECK(m.result.conformity.quad_area + m.result.conformity.curved_gap_area == Approx(cases[k].area).epsilon(1e-6));
    // The blocks, cut from the true face and carried back into the model, lie where the face does.
    const FaceDecomposition d = decompose_input_face(face, settings);
    CHECK(occt_area(d.shape) == Approx(cases[k].area).epsilon(1e-6));
    CHECK(box_distance(d.shape, cases[k].face) < 1e-6);
  }
}

TEST_CASE("no try is started once a face has taken three times the search's time limit", "[api][general][mesh][arc]") {
  // The rounded wedge takes every try when time is no object (below). With a time limit far below
  // any search's time, the first try's mesh (its search finished greedily) stands: a face of a
  // thousand parts (a plate with 89 holes) made seven such tries, minutes of them.
  const InputFace face = arc_test_face("rounded-wedge");
  DecomposeSettings settings;
  settings.policy_settings.general_time_limit = 1e-6;
  const FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
  CHECK(m.attempts == 1);
  CHECK(m.result.conformity.conformal);
}

TEST_CASE("a wedge rounded at both ends: the try that cuts smooth parts cuts it, and its mesh is kept",
          "[api][general][mesh][arc]") {
  // Face 150 of the arc benchmark (`autoblock generate --kind arcs --seed 20261202`): two corners (its
  // rounded tip's), which no cut reduces, so every try before the last but one finishes the whole face
  // with the usual template's fallback, whose mesh fans into the tip (min scaled Jacobian 0.067). That
  // try counts such a part as complex (BlockRules::cut_smooth_parts) and cuts it into blocks. (The last,
  // without tight O-grids, is not made: no decomposition has one.)
  const InputFace face = arc_test_face("rounded-wedge");
  DecomposeSettings settings = untimed_settings();
  const FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
  REQUIRE(m.result.conformity.conformal);
  CHECK(m.attempts == static_cast<int>(std::size(kSearchTries)) - 1);
  CHECK(m.cut_smooth_parts);
  CHECK(m.blocks() >= 2);
  CHECK(m.result.quality.min_scaled_jacobian > 0.1);
  CHECK(face_meshing_json("wedge", m)["cut_smooth_parts"] == true);
  // decompose keeps that decomposition (what the workbench stores), and its cuts replay and mesh the same.
  settings.occt_blocks = false;
  const FaceDecomposition d = decompose_input_face(face, settings);
  CHECK(d.region.finished.size() == m.decomposition.region.finished.size());
  CHECK(d.region.rules.cut_smooth_parts);
}

TEST_CASE("a cap with two corners over a rounded top: its poor mesh made again with the two-corner template",
          "[api][general][mesh][arc]") {
  // Face 159 of the arc benchmark (`autoblock generate --kind arcs --seed 20261202`): the search cuts
  // across it and leaves a cap whose only corners are the cut's ends, its top a chain of arcs and
  // edges. The smooth template folds on it; the usual template's fallback puts a third corner on the
  // top where the boundary turns by 12 degrees, and a quad there has an angle of 168 degrees (min
  // scaled Jacobian 0.21). The two-corner template keeps the cut's ends whole and puts its two
  // three-valent vertices inside.
  const InputFace face = arc_test_face("rounded-cap");
  const FaceMeshing m = mesh_input_face(face, untimed_settings(), MeshOptions{});
  REQUIRE(m.result.conformity.conformal);
  CHECK(m.result.two_corner);
  const RegionDecomposition& d = m.decomposition.region;
  int caps = 0;
  for (const FinishedRegion& part : d.finished) {
    if (!part.is_template || !two_corner_improves(part.region, d.rules)) continue;
    ++caps;
    CHECK(template_pieces(part.region, d.rules, true).size() == 4);
    CHECK(template_pieces(part.region, d.rules).size() == 3);  // the usual template, a fallback corner
  }
  CHECK(caps >= 1);
  CHECK(m.result.quality.min_scaled_jacobian > 0.8 * m.result.topology_bound);
}

TEST_CASE("a poor mesh is made again with the two-corner template where it beats the disk's too", "[api][general][mesh][arc]") {
  // Face 1 of the arc benchmark (`autoblock generate --kind arcs --seed 20261202`): a part with two
  // corners holds a rounded acute tip, and the disk's template takes it (its spokes split both
  // corners); its mesh was 0.51 of the bound, gmsh's 0.61. The two-corner template's pieces score
  // better, so the poor mesh is made again with it there.
  const InputFace face = arc_test_face("smooth-tip");
  const FaceMeshing m = mesh_input_face(face, untimed_settings(), MeshOptions{});
  REQUIRE(m.result.conformity.conformal);
  CHECK(m.result.two_corner);
  CHECK(face_meshing_json("tip", m)["two_corner_templates"] == true);
  const RegionDecomposition& d = m.decomposition.region;
  CHECK(std::any_of(d.finished.begin(), d.finished.end(),
                    [&](const FinishedRegion& f) { return f.is_template && two_corner_improves(f.region, d.rules); }));
  // The same blocks, meshed once without the second meshes: the disk's template, worse.
  MeshOptions options;
  options.occt_model = false;
  options.min_edge_intervals = d.min_edge_intervals;
  options.general.reward = d.reward;
  options.arc_targets = false;
  options.two_corner = false;
  const MeshResult first = mesh_region_decomposition(face, d, options);
  REQUIRE(first.conformity.conformal);
  CHECK_FALSE(first.two_corner);
  CHECK(m.result.quality.min_scaled_jacobian > first.quality.min_scaled_jacobian + 0.1);
  CHECK(m.result.block_model.blocks.size() < first.block_model.blocks.size());  // four pieces for the disk's five
}

TEST_CASE("a rounded acute tip: the arcs' chord steps as targets, not minima, keep its quads from fanning",
          "[api][general][mesh][arc]") {
  // Face 92 of the arc benchmark (`autoblock generate --kind arcs --seed 20261202`): a polygon whose acute
  // tip is rounded by an arc of several chords. The block holding the tip has the arc on one side and a
  // short side opposite; one interval per chord as a minimum makes that short side carry them all.
  const InputFace face = arc_test_face("rounded-tip");
  DecomposeSettings settings = untimed_settings();
  settings.occt_blocks = false;
  const FaceDecomposition d = decompose_input_face(face, settings);
  REQUIRE(d.region.complete());
  MeshOptions options;
  options.occt_model = false;
  options.min_edge_intervals = d.region.min_edge_intervals;
  options.general.reward = d.region.reward;
  options.arc_targets = false;
  options.two_corner = false;  // the same block model in both meshes
  const MeshResult minima = mesh_region_decomposition(face, d.region, options);
  REQUIRE(minima.conformity.conformal);
  CHECK_FALSE(minima.arc_targets);
  CHECK(minima.quality.min_scaled_jacobian < kArcTargetsBelow * minima.topology_bound);
  options.arc_targets = true;
  const MeshResult targets = mesh_region_decomposition(face, d.region, options);
  REQUIRE(targets.conformity.conformal);  // every boundary node on its arc, the chords within the rule
  CHECK(targets.arc_targets);
  // 0.270 against 0.241 measured (by more than 0.1 while the smoothing could draw quads into slivers:
  // kSmoothingEdgeRatio).
  CHECK(targets.quality.min_scaled_jacobian > minima.quality.min_scaled_jacobian + 0.02);
  CHECK(targets.mesh.quads.size() < minima.mesh.quads.size());
  // On a convex arc an edge spans at most kMeshEdgeArcSteps chord steps, on others one.
  for (size_t e = 0; e < targets.block_model.edges.size(); ++e) {
    const ModelEdge& edge = targets.block_model.edges[e];
    if (edge.arc < 0) continue;
    const CircularArc& arc = face.arcs.arcs[static_cast<size_t>(edge.arc)];
    const double step = std::fabs(arc.sweep) / arc_chord_count(arc);
    const double most = (arc.outside ? 1 : kMeshEdgeArcSteps) * step;
    CHECK(std::fabs(edge.arc_sweep) / targets.intervals.intervals[e] <= most * (1.0 + 1e-5));  // (the counts round within 1e-6)
    CHECK(minima.intervals.intervals[e] >= static_cast<int>(std::ceil(std::fabs(edge.arc_sweep) / step - 1e-6)));
  }
  // The whole route keeps it, and the report says so.
  const FaceMeshing m = mesh_input_face(face, DecomposeSettings{}, MeshOptions{});
  REQUIRE(m.result.conformity.conformal);
  CHECK(face_meshing_json("tip", m)["intervals"]["arc_targets"] == m.result.arc_targets);
}

TEST_CASE("a policy whose blocks do not mesh: mesh makes the search's tries instead, and says so",
          "[api][general][mesh][arc]") {
  // Face 78 of `autoblock generate --kind arcs --seed 20261263` (a rounded plate with 3 holes): greedy's
  // blocks do not mesh (a block with two coinciding corners).
  const InputFace face = arc_test_face("greedy-unmeshable");
  DecomposeSettings settings;
  settings.policy = "greedy";
  settings.occt_blocks = false;
  settings.mesh_tries = false;  // greedy's own decomposition
  const FaceDecomposition greedy = decompose_input_face(face, settings);
  REQUIRE(greedy.region.complete());
  CHECK(greedy.region.fallback_from.empty());
  MeshOptions options;
  options.occt_model = false;
  options.general.reward = greedy.region.reward;
  std::string why;
  try {
    mesh_region_decomposition(face, greedy.region, options);
  } catch (const std::exception& e) {
    why = e.what();
  }
  REQUIRE_FALSE(why.empty());
  settings.mesh_tries = true;
  const FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
  CHECK(m.decomposition.region.fallback_from == "greedy");
  CHECK(m.decomposition.region.fallback_reason == why);
  CHECK(m.policy() == "search");
  CHECK(m.attempts >= 2);
  REQUIRE(m.result.conformity.conformal);
  const nlohmann::json report = face_meshing_json("plate", m);
  CHECK(report["policy"] == "search");
  CHECK(report["policy_fallback"]["policy"] == "greedy");
  // decompose keeps the blocks mesh keeps, and says so too.
  const FaceDecomposition kept = decompose_input_face(face, settings);
  CHECK(kept.region.policy == "search");
  CHECK(kept.region.fallback_from == "greedy");
  CHECK(kept.region.finished.size() == m.decomposition.region.finished.size());
  CHECK(region_decomposition_json("plate", face, kept.region)["policy_fallback"]["reason"] == why);
  // A policy whose blocks mesh has no fallback.
  settings.policy = "search";
  CHECK(mesh_input_face(face, settings, MeshOptions{}).decomposition.region.fallback_from.empty());
  CHECK_FALSE(face_meshing_json("plate", mesh_input_face(face, DecomposeSettings{}, MeshOptions{})).contains("policy_fallback"));
}

TEST_CASE("a policy whose mesh fails its conformity check: mesh makes the search's tries instead, and says so",
          "[api][general][mesh][arc]") {
  // A flange of `perforated_plates.py flanges.brep 20261206 30 flanges` (its 13th face): greedy's
  // blocks mesh, but with inverted quads (a sliver between the rim and a bolt hole). The user who
  // asked for greedy gets the search's conformal mesh and the reason, not an internal error.
  const InputFace face = arc_test_face("greedy-inverted");
  DecomposeSettings settings;
  settings.policy = "greedy";
  const FaceMeshing m = mesh_input_face(face, settings, MeshOptions{});
  CHECK(m.decomposition.region.fallback_from == "greedy");
  CHECK(m.decomposition.region.fallback_reason.find("conformity check") != std::string::npos);
  CHECK(m.policy() == "search");
  CHECK(m.result.conformity.conformal);
}

TEST_CASE("a flange of four bolt holes: a square O-grid cell about each hole, blocks in the ring between",
          "[api][general][mesh][arc]") {
  // A disk of radius 50, a bore of 20, four bolt holes of radius 4 on a circle of 34 (45 degrees off
  // the axes). divide_holes halves it, divide_sector quarters it and cuts a cell about each hole; each
  // cell is an annular sector, meshed by the O-grid with its arcs as sides.
  const FaceMeshing m = meshed_arc_face("flange-four-bolts");
  CHECK(m.decomposition.region.templates == 4);  // the four O-grids
  // Four cells and eight sectors between them (two beside each cell, split where the quarters met).
  CHECK(m.decomposition.region.finished.size() == 12);
  // The O-grids' quads keep the cells' right angles (0.95 measured; the search's own cuts in the
  // quarter rings gave 0.84).
  CHECK(m.result.quality.min_scaled_jacobian > 0.9);
}

TEST_CASE("a flange of two bolt circles: chords between the circles, an O-grid cell about every hole",
          "[api][general][mesh][arc]") {
  // A disk of radius 60, a bore of 22, 16 bolt holes of radius 3 on each of two circles (32 and 48),
  // in line. divide_holes cuts sectors and chords between the circles; divide_sector, given the
  // centre its parents found where its own arcs are too short, cuts the chord between two holes in
  // line and a cell's ends: every hole gets a cell (one side along the bore or the rim, or none) and
  // its O-grid.
  const FaceMeshing m = meshed_arc_face("flange-two-circles");
  CHECK(m.decomposition.region.templates == 32);  // every bolt hole
  // 0.91 measured; the search's own cuts gave 0.75 in 7.8 s.
  CHECK(m.result.quality.min_scaled_jacobian > 0.85);
}

TEST_CASE("a flange's sector O-grids whose feet sit a hair apart on the lines between them mesh",
          "[api][general][mesh][arc]") {
  // Twelve bolt holes on one circle (a flange of the generated set): divide_holes cuts twelve
  // sectors, each an O-grid. Each places its feet on the radial lines from its own hole, neighbours'
  // feet up to 0.004 apart: round the ring, the hair-thin edges between them admitted no interval
  // counts, every try failed alike and the search's own cuts meshed the face (0.28-0.55). Made one,
  // the feet give the twelve O-grids' mesh (0.946 measured).
  const FaceMeshing m = meshed_arc_face("flange-twelve-bolts");
  CHECK(m.attempts == 1);
  CHECK(m.decomposition.region.templates == 12);
  CHECK(m.decomposition.region.finished.size() == 12);
  CHECK(m.result.block_model.snapped_feet > 0);
  CHECK(face_meshing_json("flange-twelve-bolts", m)["feet_snapped"] == true);
  CHECK(m.result.quality.min_scaled_jacobian > 0.9);
}

TEST_CASE("where feet made one leave the blocks without interval counts, the feet as placed mesh",
          "[api][general][mesh][arc]") {
  // Twenty-four bolt holes on one circle, their cells cut at both ends: some neighbours' feet are a
  // hair apart, others not, and made one where they are, the counts round the ring cannot balance
  // (the hair-thin edges left balanced them). The model as the templates place them meshes the first
  // try's blocks. Its hair-thin edges make strips of quads of one edge 0.0002 long (0.782 of the
  // bound, which the scaled Jacobian does not see): degenerate, so the tries go on, and the fourth's
  // blocks, their cuts' ends a hair apart made one too, mesh without (0.832 measured).
  const InputFace face = arc_test_face("flange-twenty-four-bolts");
  DecomposeSettings first_try = untimed_settings();
  first_try.mesh_tries = false;
  const FaceDecomposition d = decompose_input_face(face, first_try);
  REQUIRE(d.region.complete());
  CHECK(d.region.templates == 24);
  MeshOptions options;
  options.occt_model = false;
  options.min_edge_intervals = d.region.min_edge_intervals;
  options.general.reward = d.region.reward;
  const MeshResult first = mesh_region_decomposition(face, d.region, options);
  CHECK(first.conformity.conformal);
  CHECK(first.block_model.snapped_feet == 0);
  CHECK(first.block_model.feet == FeetSnap::placed);
  CHECK(first.quality.min_scaled_jacobian > 0.75 * first.bound);  // 0.782 measured
  CHECK(first.quality.max_aspect_ratio > kDegenerateEdgeRatio);
  const FaceMeshing m = meshed_arc_face("flange-twenty-four-bolts");
  CHECK(m.result.quality.max_aspect_ratio <= kDegenerateEdgeRatio);
  CHECK(m.result.block_model.snapped_feet > 0);
  CHECK(m.result.quality.min_scaled_jacobian > 0.8 * m.result.bound);
  CHECK(face_meshing_json("flange-twenty-four-bolts", m)["feet_snapped"] == (m.result.block_model.snapped_feet > 0));
}

TEST_CASE("where neither the feet made one nor the feet as placed admit counts, feet a fair way apart are made one",
          "[api][general][mesh][arc]") {
  // A rounded plate of two holes (a cap of the hex benchmark's solids): the large hole's cell is cut
  // into quarters through the hole, each quarter a template whose feet on the cuts stand 0.02-0.05
  // from its neighbour's (sides of about 0.3). Round the hole those edges admit no counts, nor do
  // they once the feet a hair apart are made one: six of seven tries failed, and the one that meshed
  // fanned at the plate's rounded top (0.052). Feet a fair way apart made one mesh the second try
  // (0.816 measured), the best of the tries (a mesh on them ends no tries: a later one may mesh
  // without them).
  const FaceMeshing m = meshed_arc_face("rounded-plate-two-holes");
  CHECK(m.result.block_model.feet == FeetSnap::far);
  CHECK(m.result.block_model.far_feet());
  CHECK(m.attempts > 2);  // its 0.86 of the topology bound would have ended the tries at the second
  CHECK(m.result.block_model.snapped_feet > 0);
  CHECK(face_meshing_json("rounded-plate-two-holes", m)["far_feet"] == true);
  CHECK(m.result.quality.min_scaled_jacobian > 0.7);
}

TEST_CASE("a bar with a row of holes close to its edges: a tight O-grid in each hole's cell, and a try without them",
          "[api][general][mesh][arc]") {
  // A bar 12.28 by 2.654 with four holes of radius 1.137 at a pitch of 3.07 (a staggered plate's
  // row): 0.19 between each hole and the bar's long edges, a sixth of a radius, no room for an O-grid's
  // box. divide_holes cuts the ligaments between the holes; each square cell takes the tight O-grid,
  // its corners spoked to the hole: four blocks, every interior node regular.
  const FaceMeshing m = meshed_arc_face("holed-bar");
  const RegionDecomposition& d = m.decomposition.region;
  REQUIRE(d.finished.size() == 4);
  for (const FinishedRegion& f : d.finished) CHECK((f.is_template && tight_ogrid_template(f.region, d.rules)));
  CHECK(m.tight_ogrids == 4);
  CHECK(m.result.quality.irregular_interior_nodes == 0);
  // The spokes split the cells' right-angled corners 41 / 49 degrees (0.707 measured).
  CHECK(m.result.quality.min_scaled_jacobian > 0.65);
  const nlohmann::json report = face_meshing_json("holed-bar", m);
  CHECK(report["tight_ogrids"] == 4);
  CHECK(report["tight_ogrid"] == true);
  // Below kRetryBelow of the bound (0.74), so every try is made, the one without tight O-grids too.
  CHECK(m.attempts == static_cast<int>(std::size(kSearchTries)));
  // That try's search finishes no cell with a tight O-grid: it cuts the cells.
  DecomposeSettings without = untimed_settings();
  without.policy_settings.general_tight_ogrid = false;
  without.mesh_tries = false;
  const FaceDecomposition cut = decompose_input_face(arc_test_face("holed-bar"), without);
  REQUIRE(cut.region.complete());
  for (const FinishedRegion& f : cut.region.finished) CHECK_FALSE((f.is_template && tight_ogrid_template(f.region, cut.region.rules)));
  CHECK(cut.region.finished.size() > 4);
}

TEST_CASE("the far feet's model of a 62-hole plate: a foot others were made one with stays", "[api][general][mesh][arc]") {
  // A plate of 62 holes (the perforated set's face 4), searched as mesh's third try under the default
  // budget (counted in work: the same decomposition on every machine). Its far feet's model
  // (FeetSnap::far) moved a foot that a neighbour's foot had been made one with, past its piece's
  // corner: an edge that three pieces used, and block_model's logic_error. Now such a foot does not
  // move far; the model builds, every edge on one or two blocks' sides.
  const InputFace face = arc_test_face("perforated-62-holes");
  const SearchTry& t = kSearchTries[2];
  DecomposeSettings settings;
  settings.occt_blocks = false;
  settings.mesh_tries = false;
  settings.corner_fraction = t.corner_fraction;
  settings.cut_smooth_parts = t.cut_smooth_parts;
  settings.policy_settings.general_tight_ogrid = t.tight_ogrid;
  settings.policy_settings.general_search_width = t.width;
  const FaceDecomposition d = decompose_input_face(face, settings);
  REQUIRE(d.region.complete());
  BlockModel far;
  REQUIRE_NOTHROW(far = block_model(d.region, d.region.rules, face.region.quantum(), false, FeetSnap::far));
  CHECK(far.far_feet());
  std::vector<int> uses(far.edges.size(), 0);
  for (const ModelBlock& block : far.blocks) {
    for (const ModelSide& side : block.sides) {
      for (const int e : side.edges) ++uses[static_cast<size_t>(e)];
    }
  }
  CHECK(*std::max_element(uses.begin(), uses.end()) <= 2);
}

TEST_CASE("decompose keeps the decomposition mesh keeps, its cuts, replayed under its rules, mesh the same",
          "[api][general][mesh]") {
  // The hexagon above, whose first try is poor: the tries keep another width, other rules or finer
  // edges, and what decompose returns (what the workbench stores) must carry them.
  const RectilinearPolygon polygon{{{29.131113, 51.346410}, {-72.385620, 6.914996}, {-80.578092, -2.340715}, {-54.793450, -21.378219}, {21.978369, -96.415473}, {28.756321, -92.866493}}, {}};
  const InputFace face = check_face(occt_face_from_polygon(polygon, 0.0, true), "hexagon");
  DecomposeSettings settings;
  settings.policy_settings.general_time_limit = 0.0;
  settings.policy_settings.general_search_width = 4;
  const FaceMeshing meshed = mesh_input_face(face, settings, MeshOptions{});
  const FaceDecomposition kept = decompose_input_face(face, settings);
  REQUIRE(kept.region.complete());
  CHECK(kept.region.cuts.size() == meshed.decomposition.region.cuts.size());
  CHECK(kept.region.rules.min_corner_degrees == meshed.decomposition.region.rules.min_corner_degrees);
  CHECK(kept.region.min_edge_intervals == meshed.min_edge_intervals);
  CHECK((kept.region.min_edge_intervals > 1 || meshed.corner_fraction != kMeshCornerFraction));  // not the default's
  CHECK(kept.block_faces.size() == kept.region.finished.size());  // cut by OpenCASCADE, as before
  const nlohmann::json report = region_decomposition_json("hexagon", face, kept.region);
  CHECK(report["rules"]["max_corner_degrees"] == kept.region.rules.max_corner_degrees);
  CHECK(report["min_edge_intervals"] == kept.region.min_edge_intervals);
  // The stored cuts, replayed with the rules and meshed with the intervals, give mesh's own mesh.
  const std::vector<RegionActionSpec> actions = region_action_specs(kept.region.cuts);
  MeshOptions options;
  options.min_edge_intervals = kept.region.min_edge_intervals;
  const FaceMeshing again = face_mesh_general(face, actions, 0, kept.region.reward, options, kept.region.rules);
  CHECK(again.result.quality.min_scaled_jacobian == Approx(meshed.result.quality.min_scaled_jacobian).epsilon(1e-9));
  CHECK(again.result.mesh.quads.size() == meshed.result.mesh.quads.size());
  CHECK(again.decomposition.region.min_edge_intervals == kept.region.min_edge_intervals);
  // One search when asked (eval): the settings' width and the face's own rules.
  settings.mesh_tries = false;
  settings.occt_blocks = false;
  const FaceDecomposition once = decompose_input_face(face, settings);
  CHECK(once.region.min_edge_intervals == 1);
  const RegionDecomposition default_rules = replay_region_decomposition(
      face.region, region_action_specs(once.region.cuts),
      [&] {
        RegionEpisodeOptions o;
        o.reward = once.region.reward;
        return o;
      }(),
      "replay");
  CHECK(default_rules.rules.max_corner_degrees == once.region.rules.max_corner_degrees);
}

TEST_CASE("general faces: grid-only actions and the paper's agent say so", "[api][general][errors]") {
  const InputFace face = check_face(general_face(5, GeneralKind::Polygon, false), "polygon");
  REQUIRE(face.is_general());
  DecomposeSettings settings;
  settings.policy = "sac-faithful";
  CHECK_THROWS_WITH(decompose_input_face(face, settings), Catch::Contains("this face has edges at other angles"));
  settings.policy = "search";
  settings.policy_settings.general_time_limit = 1.0;
  settings.occt_blocks = false;
  const FaceDecomposition searched = decompose_input_face(face, settings);
  CHECK(searched.region.complete());
  CHECK(searched.block_faces.empty());
  CHECK_THROWS_WITH(face_mesh(face, {}, 0, RewardPreset::Paper, MeshOptions{}), Catch::Contains("meshing works on faces"));
  CHECK_THROWS_AS(face_step(face, {}, 0), InputError);
}

TEST_CASE("a lookahead agent's trained policy decomposes general faces by name, the paper's agent is refused",
          "[api][general][learned]") {
  // The shipped sac-mesh and sac-paper are lookahead agents (sac/region_lookahead_policy.h); the
  // shipped sac-faithful is the paper's agent, which has no general-face version.
  const InputFace face = check_face(general_face(1301, GeneralKind::Polygon, true), "polygon");
  REQUIRE(face.is_general());
  DecomposeSettings settings;
  settings.reward.clear();  // the policy's own preset
  for (const char* name : {"sac-mesh", "sac-paper"}) {
    INFO(name);
    settings.policy = name;
    const FaceDecomposition d = decompose_input_face(face, settings);
    CHECK(d.region.complete());
    CHECK(d.region.policy == name);
    CHECK(d.region.reward == (std::string(name) == "sac-mesh" ? RewardPreset::Mesh : RewardPreset::Paper));
    CHECK(d.block_faces.size() == d.region.finished.size());
    CHECK_FALSE(d.region.time_capped);
  }
  // The general time limit bounds a learned policy too: past it greedy finishes, and the result says so.
  settings.policy = "sac-mesh";
  settings.policy_settings.general_time_limit = 1e-6;
  const FaceDecomposition capped = decompose_input_face(face, settings);
  CHECK(capped.region.complete());
  CHECK(capped.region.time_capped);
  CHECK(capped.region.policy == "sac-mesh");
  // That budget is counted work (the lookahead's candidates and graphs), not time: half of what the
  // whole decomposition counts caps it at the same choice on every run.
  settings.policy_settings.general_time_limit = 100.0;
  const FaceDecomposition whole = decompose_input_face(face, settings);
  REQUIRE_FALSE(whole.region.time_capped);
  REQUIRE(whole.region.work > 0);
  settings.policy_settings.general_time_limit = 0.5 * static_cast<double>(whole.region.work) / kSearchWorkPerSecond;
  const FaceDecomposition half = decompose_input_face(face, settings);
  CHECK(half.region.time_capped);
  CHECK(half.region.work < whole.region.work);
  for (int run = 0; run < 2; ++run) {
    const FaceDecomposition again = decompose_input_face(face, settings);
    CHECK(again.region.work == half.region.work);
    CHECK(again.region.policy_steps == half.region.policy_steps);
    REQUIRE(again.region.cuts.size() == half.region.cuts.size());
    for (size_t k = 0; k < half.region.cuts.size(); ++k) {
      CHECK(again.region.cuts[k].action.cut.origin.x == half.region.cuts[k].action.cut.origin.x);
      CHECK(again.region.cuts[k].action.cut.origin.y == half.region.cuts[k].action.cut.origin.y);
      CHECK(again.region.cuts[k].action.cut.direction.x == half.region.cuts[k].action.cut.direction.x);
    }
  }
  settings.policy_settings.general_time_limit = 2.0;
  settings.policy = "sac-faithful";
  CHECK_THROWS_WITH(decompose_input_face(face, settings), Catch::Contains("the paper's agent"));
  CHECK_THROWS_AS(decompose_input_face(face, settings), InputError);
  settings.policy = "no-such-policy";
  CHECK_THROWS_AS(decompose_input_face(face, settings), InputError);
}

TEST_CASE("vertex scores on a general face: the policy's chosen vertex scores highest, baselines and the paper's agent say why not",
          "[api][general][learned][scores]") {
  const InputFace face = check_face(general_face(1302, GeneralKind::Polygon, true), "polygon");
  REQUIRE(face.is_general());
  DecomposeSettings settings;
  settings.reward.clear();
  settings.policy = "sac-mesh";
  settings.occt_blocks = false;
  const FaceDecomposition d = decompose_input_face(face, settings);
  REQUIRE(d.region.complete());
  const std::vector<RegionActionSpec> actions = region_action_specs(d.region.cuts);
  int compared = 0;
  for (int k = 0; k < static_cast<int>(actions.size()); ++k) {
    INFO("step " << k);
    const RegionSnapshot s = face_step_general(face, actions, k, 0, d.region.reward, d.region.rules);
    REQUIRE(s.has_next);
    const std::vector<double> scores = face_vertex_scores_general(face, actions, k, "sac-mesh", 0, d.region.reward, d.region.rules);
    REQUIRE(scores.size() == s.vertices.size());
    CHECK(std::any_of(scores.begin(), scores.end(), [](double v) { return std::isfinite(v); }));
    // The deployed policy takes the best Q of its shortlist: when that action starts at a vertex, the
    // vertex scores the maximum (the policy's own progress actions, past the cap, are not its choice).
    if (s.chosen_vertex >= 0 && k < d.region.policy_steps) {
      CHECK(scores[static_cast<size_t>(s.chosen_vertex)] == *std::max_element(scores.begin(), scores.end()));
      ++compared;
    }
  }
  CHECK(compared >= 1);
  CHECK_THROWS_WITH(face_vertex_scores_general(face, actions, 0, "greedy", 0, d.region.reward, d.region.rules),
                    Catch::Contains("baseline"));
  CHECK_THROWS_WITH(face_vertex_scores_general(face, actions, 0, "sac-faithful", 0, d.region.reward, d.region.rules),
                    Catch::Contains("the paper's agent"));
  CHECK_THROWS_WITH(face_vertex_scores_general(face, actions, static_cast<int>(actions.size()), "sac-mesh", 0,
                                               d.region.reward, d.region.rules),
                    Catch::Contains("no action follows"));
}

TEST_CASE("a hole whose circle is two half arcs meshes with a node at each join", "[api][arc]") {
  // As many CAD systems write a drilled hole: two half circles, joined at two vertices of the face.
  // Smoothing once slid the join's node along the circle, leaving the mesh without a node at the
  // face's vertex and failing its conformity check (a 22 x 15 plate did; a 20 x 15 one did not).
  for (const double w : {20.0, 22.0, 40.0}) {
    const gp_Pnt c(w / 2, 7.5, 0);
    const gp_Pnt right(c.X() + 5, c.Y(), 0), top(c.X(), c.Y() + 5, 0), left(c.X() - 5, c.Y(), 0), bottom(c.X(), c.Y() - 5, 0);
    BRepBuilderAPI_MakeWire hole(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(right, top, left).Value()).Edge(),
                                 BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(left, bottom, right).Value()).Edge());
    BRepBuilderAPI_MakePolygon outer(gp_Pnt(0, 0, 0), gp_Pnt(w, 0, 0), gp_Pnt(w, 15, 0), gp_Pnt(0, 15, 0), true);
    BRepBuilderAPI_MakeFace make(outer.Wire(), true);
    make.Add(TopoDS::Wire(hole.Wire().Reversed()));
    const TopoDS_Face plate = make.Face();
    REQUIRE(occt_shape_valid(plate));
    REQUIRE(occt_area(plate) == Approx(w * 15 - M_PI * 25));
    INFO("width " << w);
    const InputFace face = input_face_from_occt(plate, "plate with a two-arc hole");
    REQUIRE(face.arcs.arcs.size() == 2);
    const FaceMeshing m = mesh_input_face(face, untimed_settings(), MeshOptions{});
    CHECK(m.result.conformity.conformal);
    CHECK(m.result.smoothing.sweeps > 0);
    // A node at each join (within the lattice's few quanta that every vertex of a general face is rounded by).
    for (const gp_Pnt& join : {right, left}) {
      double nearest = HUGE_VAL;
      for (const Point2& p : m.result.mesh.nodes) nearest = std::min(nearest, std::hypot(p.x - join.X(), p.y - join.Y()));
      CHECK(nearest <= face.arcs.tolerance);
    }
    CHECK(face.arcs.tolerance < 1e-6 * w);
  }
}
