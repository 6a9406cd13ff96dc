// autoblock_native: the AutoBlock core for Python (FreeCAD's Python 3.11), deliberately thin.
//
// Every function converts its inputs, calls one entry point of core/api (face_actions.h,
// catalog.h, solid_meshing.h) with the GIL released, and converts the result. Shapes cross as BREP text (FreeCAD:
// shape.exportBrepToString() / Part.Shape().importBrepFromString()); everything else as str, int,
// float, tuple, list and dict. No C++ type is registered with pybind11: FreeCAD's own pybind11
// modules share pybind11's internals with this one.
//
// Errors: autoblock::InputError (the user's input is wrong) -> ValueError; any other failure
// (std::exception, OpenCASCADE's Standard_Failure) -> RuntimeError.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Standard_Failure.hxx>

#include <atomic>
#include <functional>
#include <cstdio>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/api/face_actions.h"
#include "core/api/face_meshing.h"
#include "core/api/solid_meshing.h"
#include "core/api/training_job.h"
#include "core/baselines/min_rectangles.h"
#include "core/common/error.h"
#include "core/common/format.h"
#include "core/geometry/occt_face.h"
#include "core/io/face_selection.h"
#include "core/io/decomposition_json.h"
#include "core/io/shape_file.h"
#include "core/io/svg_picture.h"
#include "core/io/text_file.h"
#include "core/mesh/hex_export.h"
#include "core/mesh/mesh_export.h"

namespace py = pybind11;
using namespace autoblock;

namespace {

// The face held by BREP text (exactly one face), checked; read and checked first in a child
// process (shape_file.h), so malformed text cannot hang or crash FreeCAD. A face whose edges run
// along two perpendicular directions goes to the grid engine, any other to the general engine.
InputFace face_of(const std::string& brep, const std::string& source) { return input_face_from_brep_text(brep, source); }

CutDirection direction_of(const std::string& name) {
  if (name == "horizontal") return CutDirection::Horizontal;
  if (name == "vertical") return CutDirection::Vertical;
  throw InputError("unknown cut direction '" + name + "' (expected horizontal or vertical)");
}

// A cut sequence as Python passes it, either kind (converted with the GIL held):
//   grid faces:    [(part, x, y, 'horizontal'|'vertical'), ...]  (a vertex and an axis);
//   general faces: [(part, kind, ox, oy, dx, dy, forced), ...]   (kind 'full' or 'partial': origin and
//                  direction; 'template': (part, 'template') is enough; forced optional, False).
struct Sequence {
  bool general = false;
  std::vector<CutSpec> grid;
  std::vector<RegionActionSpec> region;
  void check_for(const InputFace& face) const {
    if (face.is_general() && !general && !grid.empty()) {
      throw InputError(face.source + ": this face has edges at other angles: its cuts are (part, kind, origin x, "
                       "origin y, direction x, direction y, forced), not (part, x, y, direction)");
    }
    if (!face.is_general() && general && !region.empty()) {
      throw InputError(face.source + ": this face's edges run along two perpendicular directions: its cuts are "
                       "(part, x, y, 'horizontal' or 'vertical'), not (part, kind, origin, direction)");
    }
  }
};

Sequence sequence_of(const py::object& cuts) {
  Sequence out;
  for (const py::handle item : cuts) {
    const py::tuple t = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
    if (t.size() >= 2 && py::isinstance<py::str>(t[1])) {
      out.general = true;
      RegionActionSpec spec;
      spec.part_id = t[0].cast<int>();
      spec.action = region_action_of_kind(t[1].cast<std::string>());
      if (spec.action.kind == RegionAction::Kind::Cut) {
        if (t.size() != 6 && t.size() != 7) {
          throw InputError("a general cut is (part, kind, origin x, origin y, direction x, direction y[, forced]), got " +
                           std::to_string(t.size()) + " values");
        }
        spec.action.cut.origin = {t[2].cast<double>(), t[3].cast<double>()};
        spec.action.cut.direction = {t[4].cast<double>(), t[5].cast<double>()};
        spec.action.cut.forced = t.size() == 7 && t[6].cast<bool>();
      }
      out.region.push_back(spec);
    } else {
      if (t.size() != 4) throw InputError("a cut is (part, x, y, 'horizontal' or 'vertical'), got " + std::to_string(t.size()) + " values");
      out.grid.push_back(CutSpec{t[0].cast<int>(), Point2{t[1].cast<double>(), t[2].cast<double>()},
                                 direction_of(t[3].cast<std::string>())});
    }
  }
  if (out.general && !out.grid.empty()) throw InputError("a cut sequence mixes grid cuts and general cuts");
  return out;
}

// JSON (core/io's serialisers) as Python data.
py::object python_of(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

py::tuple xy(const Point2& p) { return py::make_tuple(p.x, p.y); }

py::list ring_list(const Ring& ring) {
  py::list out;
  for (const Point2& p : ring) out.append(xy(p));
  return out;
}

py::dict capabilities_dict() {
  const Capabilities c = capabilities();
  py::dict d;
  d["learned_policies"] = c.learned_policies;
  d["training"] = c.training;
  d["vertex_scores"] = c.vertex_scores;
  d["meshing"] = c.meshing;
  return d;
}

py::dict face_dict(const InputFace& face) {
  py::dict d;
  // A general face's loops are its region's (on the face's lattice), a rectilinear face's its polygon's.
  const bool general = face.is_general();
  const Ring& outer = general ? face.region.outer() : face.planar.polygon.outer;
  const std::vector<Ring>& hole_rings = general ? face.region.holes() : face.planar.polygon.holes;
  size_t corners = outer.size();
  for (const Ring& hole : hole_rings) corners += hole.size();
  const Box box = ring_bbox(outer);
  d["source"] = face.source;
  d["general"] = general;
  d["z"] = face.planar.z;
  d["normal_up"] = face.planar.normal_up;
  d["corners"] = corners;
  d["holes"] = hole_rings.size();
  d["area"] = general ? face.region.area() : polygon_area(face.planar.polygon);
  d["bbox"] = py::make_tuple(box.xmin, box.ymin, box.xmax, box.ymax);
  d["outer"] = ring_list(outer);
  py::list holes;
  for (const Ring& hole : hole_rings) holes.append(ring_list(hole));
  d["hole_rings"] = holes;
  return d;
}

// The core's frame (occt_face.h, face_frame) of the face held by BREP text, as 12 numbers: the row-major
// rotation, then the translation (a point p of the frame is the model's rotation p + translation). The
// identity when the text holds no single face or OpenCASCADE cannot evaluate it: the checks that follow
// (check_face, decompose) then say what is wrong, with the face in the model's coordinates.
// A placement as 12 numbers: the row-major rotation, then the translation.
std::vector<double> placement_numbers(const Placement& frame) {
  std::vector<double> numbers(frame.rotation.begin(), frame.rotation.end());
  numbers.insert(numbers.end(), frame.translation.begin(), frame.translation.end());
  return numbers;
}

std::vector<double> face_frame_py(const std::string& brep) {
  Placement frame;
  {
    py::gil_scoped_release release;
    try {
      frame = face_frame(select_face(read_brep_text(brep), "face", 0));
    } catch (const InputError&) {
      frame = Placement{};
    } catch (const Standard_Failure&) {
      frame = Placement{};
    }
  }
  return placement_numbers(frame);
}

py::dict check_face_py(const std::string& brep, const std::string& source) {
  InputFace face;
  int minimum = 0;
  {
    py::gil_scoped_release release;
    face = face_of(brep, source);
    if (!face.is_general()) minimum = min_rectangles(face.grid.whole);
  }
  py::dict d = face_dict(face);
  // No known minimum for a general face (the exact search is the grid engine's).
  d["min_blocks"] = face.is_general() ? py::object(py::none()) : py::object(py::int_(minimum));
  return d;
}

// A decomposition's results as text (made without the GIL): its blocks and their merged shape as
// BREP text (none when it was made without them: a solid's cap), and a general face's JSON report
// (region_decomposition_json, the CLI's).
struct Written {
  std::vector<std::string> blocks;
  std::string shape;
  nlohmann::json report;
  Written() = default;
  Written(const FaceDecomposition& result, const std::string& source) {
    for (const TopoDS_Face& block : result.block_faces) blocks.push_back(write_brep_text(block));
    if (!result.shape.IsNull()) shape = write_brep_text(result.shape);  // none from the mesh pipeline
    if (result.general()) report = region_decomposition_json(source, result.face, result.region);
  }
};

// A general decomposition for Python: the CLI's JSON report as data, with the blocks as BREP text (and
// the report's block outlines as "outlines"), their merged shape, the step cap asked for and the face's
// figures.
py::dict general_decomposition_dict(const Written& written, int max_steps, const InputFace& face) {
  py::dict out = python_of(written.report).cast<py::dict>();
  out["outlines"] = out["blocks"];
  out["blocks"] = written.blocks;
  out["shape"] = written.shape;
  out["min_blocks"] = py::none();
  out["max_steps"] = max_steps;
  out["report_face"] = out["face"];
  out["face"] = face_dict(face);
  return out;
}

// A decomposition's settings as decompose() and mesh_solid() take them ('' policy or reward: the default;
// general_time_limit < 0: the core's default).
DecomposeSettings settings_of(const std::string& policy, const std::string& reward, std::uint64_t seed, double time_limit,
                              int max_steps, double general_time_limit) {
  DecomposeSettings settings;
  if (!policy.empty()) settings.policy = policy;
  if (!reward.empty()) settings.reward = reward;
  settings.policy_settings.seed = seed;
  settings.policy_settings.time_limit = time_limit;
  if (general_time_limit >= 0) settings.policy_settings.general_time_limit = general_time_limit;
  settings.max_steps = max_steps;
  return settings;
}

py::dict decomposition_dict(const FaceDecomposition& result, const Written& written, int max_steps);

py::dict decompose_py(const std::string& brep, const std::string& policy, const std::string& reward, std::uint64_t seed,
                      double time_limit, int max_steps, const std::string& source, double general_time_limit) {
  const DecomposeSettings settings = settings_of(policy, reward, seed, time_limit, max_steps, general_time_limit);
  FaceDecomposition result;
  Written written;
  {
    py::gil_scoped_release release;
    result = decompose_input_face(face_of(brep, source), settings);
    written = Written(result, source);
  }
  return decomposition_dict(result, written, max_steps);
}

// A decomposition for Python, either engine (decompose's dict; a solid's cap in mesh_solid's).
py::dict decomposition_dict(const FaceDecomposition& result, const Written& written, int max_steps) {
  if (result.general()) return general_decomposition_dict(written, max_steps, result.face);
  const std::vector<std::string>& blocks = written.blocks;
  const std::string& shape = written.shape;
  const Decomposition& d = result.decomposition;
  py::dict out;
  out["engine"] = "grid";
  out["policy"] = d.policy;
  out["reward"] = reward_preset_name(result.decomposition.reward);
  out["blocks"] = blocks;
  out["shape"] = shape;
  py::list boxes;
  for (const Box& b : d.blocks) boxes.append(py::make_tuple(b.xmin, b.ymin, b.xmax, b.ymax));
  out["boxes"] = boxes;
  py::list cuts;
  for (const CutRecord& c : d.cuts) {
    py::dict cut;
    cut["part"] = c.part_id;
    cut["vertex"] = xy(c.position);
    cut["direction"] = direction_name(c.direction);
    cut["n_parts"] = c.n_parts;
    cut["reward"] = c.reward;
    cut["children"] = c.children;
    cuts.append(cut);
  }
  out["cuts"] = cuts;
  out["return"] = d.total_return;
  out["n_blocks"] = d.blocks.size();
  out["n_unfinished"] = d.unfinished.size();
  out["min_blocks"] = d.min_blocks;
  out["status"] = status_name(d.status);
  out["complete"] = d.complete();
  out["truncated"] = d.truncated();
  out["time_capped"] = d.time_capped;
  out["seconds"] = d.seconds;
  out["max_steps"] = max_steps;
  out["face"] = face_dict(result.face);
  return out;
}

// What every step dict starts with (either engine).
py::dict step_head(const char* engine, int step, int steps, int blocks, double ret, EpisodeStatus status,
                   const InputFace& face) {
  py::dict out;
  out["engine"] = engine;
  out["step"] = step;
  out["steps"] = steps;
  out["blocks"] = blocks;
  out["return"] = ret;
  out["status"] = status_name(status);
  out["z"] = face.planar.z;
  out["normal_up"] = face.planar.normal_up;
  return out;
}

py::dict piece_dict(int id, bool block, const Ring& outer, const std::vector<Ring>& hole_rings) {
  py::dict p;
  p["id"] = id;
  p["block"] = block;
  p["outer"] = ring_list(outer);
  py::list holes;
  for (const Ring& hole : hole_rings) holes.append(ring_list(hole));
  p["holes"] = holes;
  return p;
}

// The next cut's line (segments with ends a, b: Segment or Chord), reward and pieces left.
template <class SegmentT>
void finish_next(py::dict& next, const std::vector<SegmentT>& segments, double reward, int n_parts) {
  py::list line;
  for (const SegmentT& segment : segments) line.append(py::make_tuple(xy(segment.a), xy(segment.b)));
  next["line"] = line;
  next["reward"] = reward;
  next["n_parts"] = n_parts;
}

// A general face's step (region_snapshot.h) for Python: as step_py's, with the next action's kind,
// origin, direction (a vector) and chords as its line; "chosen" is -1 when the origin lies on an edge
// or the action is a template.
py::dict general_step_dict(const RegionSnapshot& s, const InputFace& face) {
  py::dict out = step_head("general", s.step, s.steps, s.blocks, s.return_so_far, s.status, face);
  out["templates"] = s.templates;
  out["quantum"] = face.region.quantum();  // the lattice the pieces' corners lie on (region.h)
  py::list pieces;
  for (const RegionSnapshotPiece& piece : s.pieces) {
    py::dict p = piece_dict(piece.id, piece.finished, piece.region.outer(), piece.region.holes());
    p["template"] = piece.is_template;
    pieces.append(p);
  }
  out["pieces"] = pieces;
  if (!s.has_next) {
    out["next"] = py::none();
    return out;
  }
  py::dict next;
  next["part"] = s.current_part_id;
  next["kind"] = action_kind_name(s.action);
  next["vertices"] = ring_list(s.vertices);
  next["chosen"] = s.chosen_vertex;
  const bool cut = s.action.kind == RegionAction::Kind::Cut;
  next["origin"] = cut ? py::object(xy(s.action.cut.origin)) : py::object(py::none());
  next["direction"] = cut ? py::object(xy(s.action.cut.direction)) : py::object(py::none());
  next["forced"] = cut && s.action.cut.forced;
  finish_next(next, s.chords, s.reward, s.n_parts);
  out["next"] = next;
  return out;
}

// A general sequence's block rules as a report gives them ("rules": min corner, max corner and flat
// tolerance, degrees); none ([]): the face's own for the mesh preset, as a search makes them.
std::optional<BlockRules> rules_of(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  if (values.size() != 3) {
    throw InputError("block rules are 3 numbers (min corner, max corner, flat tolerance; degrees), got " +
                     std::to_string(values.size()));
  }
  BlockRules rules{values[0], values[1], values[2]};
  if (!(rules.min_corner_degrees > 0.0 && rules.min_corner_degrees < rules.max_corner_degrees &&
        rules.max_corner_degrees < 180.0 && rules.flat_tolerance_degrees >= 0.0 && rules.flat_tolerance_degrees < 90.0)) {
    throw InputError("block rules: expected 0 < min corner < max corner < 180 and a flat tolerance in [0, 90) degrees");
  }
  return rules;
}

// A general decomposition's minimum intervals per model edge, as its report gives them.
int min_edge_intervals_of(int value) {
  if (value < 1 || value > 1000) throw InputError("min_edge_intervals: expected 1 to 1000");
  return value;
}

py::dict step_py(const std::string& brep, const py::object& cuts, int step, int max_steps, const std::string& reward,
                 const std::string& source, const std::vector<double>& rules) {
  const std::optional<BlockRules> block_rules = rules_of(rules);
  const RewardPreset preset = reward_preset_by_name(reward);
  const Sequence sequence = sequence_of(cuts);
  InputFace face;
  EpisodeSnapshot s;
  RegionSnapshot general;
  {
    py::gil_scoped_release release;
    face = face_of(brep, source);
    sequence.check_for(face);
    if (face.is_general()) {
      general = face_step_general(face, sequence.region, step, max_steps, preset, block_rules);
    } else {
      s = face_step(face, sequence.grid, step, max_steps, preset);
    }
  }
  if (face.is_general()) return general_step_dict(general, face);
  py::dict out = step_head("grid", s.step, s.steps, s.blocks, s.return_so_far, s.status, face);
  py::list pieces;
  for (const SnapshotPiece& piece : s.pieces) {
    pieces.append(piece_dict(piece.id, piece.block, piece.polygon.outer, piece.polygon.holes));
  }
  out["pieces"] = pieces;
  if (s.has_next) {
    py::dict next;
    next["part"] = s.current_part_id;
    next["vertices"] = ring_list(s.vertices);
    next["chosen"] = s.chosen_vertex;
    next["vertex"] = xy(s.vertices[static_cast<size_t>(s.chosen_vertex)]);
    next["direction"] = direction_name(s.direction);
    finish_next(next, s.line, s.reward, s.n_parts);
    out["next"] = next;
  } else {
    out["next"] = py::none();
  }
  return out;
}

// A general face's cut sequence replayed (no search): as decompose_py's general dict.
py::dict replay_py(const std::string& brep, const py::object& cuts, int max_steps, const std::string& reward,
                   const std::string& policy, const std::string& source, const std::vector<double>& rules,
                   int min_edge_intervals) {
  const RewardPreset preset = reward_preset_by_name(reward);
  const std::optional<BlockRules> block_rules = rules_of(rules);
  const int intervals = min_edge_intervals_of(min_edge_intervals);
  const Sequence sequence = sequence_of(cuts);
  FaceDecomposition result;
  Written written;
  {
    py::gil_scoped_release release;
    const InputFace face = face_of(brep, source);
    if (!face.is_general()) {
      throw InputError(face.source + ": replay takes the cut sequence of a face with edges at other angles; this "
                       "face's edges run along two perpendicular directions (decompose it)");
    }
    sequence.check_for(face);
    result = face_replay_general(face, sequence.region, max_steps, preset, policy, true, block_rules);
    result.region.min_edge_intervals = intervals;
    written = Written(result, source);
  }
  return general_decomposition_dict(written, max_steps, result.face);
}

py::dict policy_info_py(const std::string& spec) {
  std::shared_ptr<const PolicySource> source;
  {
    py::gil_scoped_release release;
    source = policy_source(spec, PolicySettings{});
  }
  py::dict d;
  d["name"] = source->name();
  d["learned"] = source->learned();
  d["reward"] = reward_preset_name(source->reward());
  // Whose value network scores the vertices (auto: its learned fallback's); None for a baseline.
  const std::string scorer = source->scoring_policy_name();
  d["scores_by"] = scorer.empty() ? py::object(py::none()) : py::object(py::str(scorer));
  // A second network for general faces (a policy file of two networks, `autoblock combine`).
  d["general_network"] = source->learned() && source->learned_policy()->general_network();
  return d;
}

std::string combine_policies_py(const std::string& grid, const std::string& general, const std::string& output) {
  py::gil_scoped_release release;
  return combine_policies(grid, general, output);
}

std::vector<double> vertex_scores_py(const std::string& brep, const py::object& cuts, int step, const std::string& policy,
                                     int max_steps, const std::string& reward, const std::string& source,
                                     const std::vector<double>& rules) {
  const std::optional<BlockRules> block_rules = rules_of(rules);
  const RewardPreset preset = reward_preset_by_name(reward);
  const Sequence sequence = sequence_of(cuts);
  py::gil_scoped_release release;
  const InputFace face = face_of(brep, source);
  sequence.check_for(face);
  if (face.is_general()) return face_vertex_scores_general(face, sequence.region, step, policy, max_steps, preset, block_rules);
  return face_vertex_scores(face, sequence.grid, step, policy, max_steps, preset);
}

MeshPlacement placement_of(const std::vector<double>& values) {
  MeshPlacement placement;
  if (values.empty()) return placement;
  if (values.size() != 12) {
    throw InputError("a mesh placement is 12 numbers (a row-major 3 x 3 rotation, then the translation), got " +
                     std::to_string(values.size()));
  }
  for (size_t k = 0; k < 9; ++k) placement.rotation[k] = values[k];
  for (size_t k = 0; k < 3; ++k) placement.translation[k] = values[9 + k];
  return placement;
}

// The quality figures a quad mesh (MeshQuality) and a hexahedral one (HexMeshQuality) share.
template <class Quality>
py::dict quality_dict(const Quality& q) {
  py::dict quality;
  quality["min_scaled_jacobian"] = q.min_scaled_jacobian;
  quality["mean_scaled_jacobian"] = q.mean_scaled_jacobian;
  quality["max_aspect_ratio"] = q.max_aspect_ratio;
  quality["max_skew"] = q.max_skew;
  return quality;
}

py::dict mesh_py(const std::string& brep, const py::object& cuts, double size, int max_steps, const std::string& reward,
                 const std::string& out, const std::vector<double>& placement, const std::string& source,
                 const std::vector<double>& rules, int min_edge_intervals) {
  const RewardPreset preset = reward_preset_by_name(reward);
  const std::optional<BlockRules> block_rules = rules_of(rules);
  const int intervals = min_edge_intervals_of(min_edge_intervals);
  const Sequence sequence = sequence_of(cuts);
  const MeshPlacement where = placement_of(placement);
  if (!out.empty() && !is_mesh_file_name(out)) throw InputError(out + ": expected a .msh, .vtu or .inp file");
  MeshResult result;
  {
    py::gil_scoped_release release;
    MeshOptions options;
    options.size = size;
    options.occt_model = false;  // the mesh and its report need no OpenCASCADE model of the blocks
    const InputFace face = face_of(brep, source);
    sequence.check_for(face);
    if (face.is_general()) options.min_edge_intervals = intervals;
    result = face.is_general() ? face_mesh_general(face, sequence.region, max_steps, preset, options, block_rules).result
                               : face_mesh(face, sequence.grid, max_steps, preset, options).result;
    if (!out.empty()) write_mesh_file(out, result.mesh, where);
  }
  const QuadMesh& mesh = result.mesh;
  const MeshQuality& q = result.quality;
  py::dict d;
  py::list nodes;
  for (const Point2& p : mesh.nodes) nodes.append(py::make_tuple(p.x, p.y, mesh.z));
  d["nodes"] = nodes;
  py::list quads;
  for (const auto& quad : mesh.quads) quads.append(py::make_tuple(quad[0], quad[1], quad[2], quad[3]));
  d["quads"] = quads;
  d["quad_block"] = mesh.quad_block;
  d["blocks"] = mesh.blocks;
  d["target_size"] = result.intervals.target_size;
  d["default_size"] = result.default_size;
  d["max_relative_deviation"] = result.intervals.max_relative_deviation;
  py::dict quality = quality_dict(q);
  quality["min_angle"] = q.min_angle;
  quality["max_angle"] = q.max_angle;
  quality["irregular_interior_vertices"] = q.irregular_interior_nodes;
  quality["bound"] = result.bound;  // the face's scaled-Jacobian bound (1 for a rectilinear face)
  quality["topology_bound"] = result.topology_bound;  // with its holes and smooth loops (block.h)
  d["quality"] = quality;
  d["conformal"] = result.conformity.conformal;
  d["file"] = out;
  return d;
}

// The swept solid held by BREP text (one solid, a compound holding one, or a closed shell), read and
// checked first in a child process (shape_file.h) as a face is.
SweptSolid solid_of(const std::string& brep, const std::string& source) {
  TopoDS_Shape shape;
  try {
    shape = read_brep_text(brep, [&](const TopoDS_Shape& read) { swept_solid_from_shape(read, source); });
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.rfind(source, 0) == 0) throw;
    throw InputError(source + ": " + message);  // the reader's messages do not know the source
  }
  return swept_solid_from_shape(shape, source);
}

py::tuple xyz(const Point3& p) { return py::make_tuple(p[0], p[1], p[2]); }

py::dict solid_dict(const SweptSolid& solid) {
  py::dict d;
  d["source"] = solid.source;
  d["caps"] = py::make_tuple(solid.bottom, solid.top);
  d["sweep"] = py::make_tuple(solid.sweep.X(), solid.sweep.Y(), solid.sweep.Z());
  d["volume"] = solid.volume;
  d["area"] = solid.area;
  d["faces"] = solid.faces.size();
  return d;
}

py::dict check_solid_py(const std::string& brep, const std::string& source) {
  SweptSolid solid;
  {
    py::gil_scoped_release release;
    solid = solid_of(brep, source);
  }
  return solid_dict(solid);
}

// What mesh_solid makes without the GIL: the meshing, its prism blocks as BREP text.
struct SolidWritten {
  SolidMeshing meshing;
  std::vector<std::string> blocks;
  std::string shape;
  Written cap;            // the cap's decomposition (its general report)
  std::string cap_brep;   // the cap in its own frame
};

py::dict mesh_solid_py(const std::string& brep, const std::string& policy, const std::string& reward, std::uint64_t seed,
                       double time_limit, int max_steps, double size, int layers, double grading, bool blocks,
                       const std::string& source, double general_time_limit, const std::string& out_file,
                       const std::string& element) {
  const DecomposeSettings settings = settings_of(policy, reward, seed, time_limit, max_steps, general_time_limit);
  if (!out_file.empty() && !is_mesh_file_name(out_file)) {
    throw InputError(out_file + ": expected a .msh, .vtu or .inp file");
  }
  if (element != "C3D8" && element != "C3D8I") throw InputError("unknown element '" + element + "' (expected C3D8 or C3D8I)");
  SolidMeshOptions options;
  options.cap.size = size;
  options.layers = layers;
  options.grading = grading;
  SolidWritten out;
  {
    py::gil_scoped_release release;
    out.meshing = mesh_swept_solid(solid_of(brep, source), settings, options);
    out.cap = Written(out.meshing.cap.decomposition, out.meshing.cap.decomposition.face.source);
    out.cap_brep = write_brep_text(out.meshing.cap.decomposition.face.occt);
    if (!out_file.empty()) {
      require_conformal(out.meshing);  // as the CLI: a mesh that failed the check is not written
      write_text_file(out_file, mesh_file_text(out_file, out.meshing.mesh, element));
    }
    if (blocks) {
      const PrismBlocks prisms = solid_meshing_blocks(out.meshing);
      for (const TopoDS_Solid& prism : prisms.solids) out.blocks.push_back(write_brep_text(prism));
      out.shape = write_brep_text(prisms.compound);
    }
  }
  const SolidMeshing& m = out.meshing;
  const HexMesh& mesh = m.mesh;
  py::dict d = solid_dict(m.solid);
  py::list nodes;
  for (const Point3& p : mesh.nodes) nodes.append(xyz(p));
  d["nodes"] = nodes;
  py::list hexes;
  for (const auto& h : mesh.hexes) hexes.append(py::make_tuple(h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]));
  d["hexes"] = hexes;
  d["hex_block"] = mesh.hex_block;
  d["n_blocks"] = mesh.blocks;
  d["layers"] = mesh.layers;
  d["policy"] = m.cap.policy();
  d["general"] = m.cap.general();
  d["target_size"] = m.target_size;
  d["default_size"] = m.default_size;
  d["grading"] = m.grading;
  d["seconds"] = m.seconds;
  const HexMeshQuality& q = m.quality;
  py::dict quality = quality_dict(q);
  quality["mean_aspect_ratio"] = q.mean_aspect_ratio;
  quality["edges"] = q.edges;
  quality["irregular_edges"] = q.irregular_edges;
  quality["irregular_interior_edges"] = q.irregular_interior_edges;
  d["quality"] = quality;
  const HexConformity& c = m.conformity;
  d["conformal"] = c.conformal;
  d["problem"] = c.problem;
  d["hex_volume"] = c.hex_volume;
  d["blocks"] = out.blocks;
  d["shape"] = out.shape;
  d["file"] = out_file;
  // The cap's decomposition as decompose gives a face's (without blocks), with the cap in its frame (BREP
  // text) and that frame (12 numbers, as face_frame): what stepping through its cuts needs.
  const FaceDecomposition& cap = m.cap.decomposition;
  py::dict cap_dict = decomposition_dict(cap, out.cap, settings.max_steps);
  cap_dict["brep"] = out.cap_brep;
  cap_dict["frame"] = placement_numbers(cap.face.frame);
  cap_dict["face_number"] = m.solid.bottom;
  d["cap"] = cap_dict;
  return d;
}

// Training options as TrainingRequest.to_options() gives them (src/AutoBlock/training.py).
GeneratedSet generated_of(const py::dict& d) {
  GeneratedSet set;
  if (d.contains("count")) set.count = d["count"].cast<int>();
  if (d.contains("seed")) set.seed = d["seed"].cast<std::uint64_t>();
  if (d.contains("min_rects")) set.options.min_rects = d["min_rects"].cast<int>();
  if (d.contains("max_rects")) set.options.max_rects = d["max_rects"].cast<int>();
  if (d.contains("holes")) set.options.holes = d["holes"].cast<bool>();
  if (d.contains("general")) set.general = d["general"].cast<int>();
  if (d.contains("arcs")) set.arcs = d["arcs"].cast<int>();
  return set;
}

template <class T>
T option(const py::dict& options, const char* key, T fallback) {
  return options.contains(key) && !options[key].is_none() ? options[key].cast<T>() : fallback;
}

py::dict train_py(const py::dict& options, const py::object& progress) {
  TrainingJob job;
  job.output = option<std::string>(options, "output", "");
  job.checkpoint = option<std::string>(options, "checkpoint", "");
  job.resume = option<bool>(options, "resume", false);
  job.init = option<std::string>(options, "init", "");
  job.train_folder = option<std::string>(options, "train_folder", "");
  job.test_folder = option<std::string>(options, "test_folder", "");
  if (options.contains("train_generate")) job.train_generate = generated_of(options["train_generate"].cast<py::dict>());
  if (options.contains("test_generate")) job.test_generate = generated_of(options["test_generate"].cast<py::dict>());
  job.episodes = option<int>(options, "episodes", job.episodes);
  job.seed = option<std::uint64_t>(options, "seed", 0);
  job.reward = option<std::string>(options, "reward", job.reward);
  if (job.reward.empty()) job.reward = "paper";
  job.agent = option<std::string>(options, "agent", job.agent);
  job.threads = option<int>(options, "threads", 1);
  job.eval_every = option<int>(options, "eval_every", job.eval_every);
  job.max_steps = option<int>(options, "max_steps", 0);

  // The callbacks run on this (GIL-free) thread: they take the GIL for Python and never let a Python
  // exception cross the core; a failed callback stops the run and is reported after it.
  std::atomic<bool> stop{false};
  std::string callback_error;
  TrainingCallbacks callbacks;
  callbacks.should_stop = [&] { return stop.load(); };
  // Calls progress with the event fill() makes under the GIL; False back, or a failure, stops the run.
  // (Declared here: the callbacks below hold it by reference until the run ends.)
  const auto report = [&](const std::function<void(py::dict&)>& fill) {
    if (stop) return;
    py::gil_scoped_acquire acquire;
    try {
      py::dict event;
      fill(event);
      event["episodes"] = job.episodes;
      const py::object answer = progress(event);
      if (!answer.is_none() && !answer.cast<bool>()) stop = true;
    } catch (py::error_already_set& e) {
      callback_error = e.what();
      stop = true;
    }
  };
  if (!progress.is_none()) {
    callbacks.on_episode = [&](const EpisodeRecord& r, bool earlier) {
      report([&](py::dict& event) {
        event["episode"] = r.episode;
        event["return"] = r.ret;
        event["blocks"] = r.blocks;
        event["steps"] = r.steps;
        event["complete"] = r.complete;
        event["shape"] = r.shape;
        event["seconds"] = r.wall_seconds;
        event["test_return"] = r.evaluated ? py::object(py::float_(r.test_return)) : py::object(py::none());
        event["earlier"] = earlier;
      });
    };
    // What the run does before its first episode: an event with "status" (no "episode").
    callbacks.on_status = [&](const std::string& line) { report([&](py::dict& event) { event["status"] = line; }); };
  }
  TrainingOutcome outcome;
  {
    py::gil_scoped_release release;
    outcome = run_training_job(job, callbacks);
  }
  if (!callback_error.empty()) throw std::runtime_error("training stopped: the progress callback failed: " + callback_error);
  py::dict d;
  d["cancelled"] = outcome.cancelled;
  d["episodes_done"] = outcome.episodes_done;
  d["episodes"] = outcome.episodes;
  d["reward"] = outcome.reward;
  d["policy_file"] = outcome.policy_file.empty() ? py::object(py::none()) : py::object(py::str(outcome.policy_file));
  d["checkpoint"] = outcome.checkpoint;
  d["log"] = outcome.log;
  d["curves"] = outcome.curves;
  d["final_test_return"] = outcome.final_test_return;
  d["optimal_test_return"] = outcome.optimal_test_return;
  d["greedy_test_return"] = outcome.greedy_test_return;
  d["wall_seconds"] = outcome.wall_seconds;
  return d;
}

std::vector<std::tuple<double, double, double>> block_colours(int count) {
  std::vector<std::tuple<double, double, double>> colours;
  for (int i = 0; i < count; ++i) {
    unsigned r = 0, g = 0, b = 0;
    std::sscanf(block_colour(i).c_str(), "#%02x%02x%02x", &r, &g, &b);
    colours.emplace_back(r / 255.0, g / 255.0, b / 255.0);
  }
  return colours;
}

}  // namespace

PYBIND11_MODULE(autoblock_native, m) {
  m.doc() = "The AutoBlock core (block decomposition of planar faces: rectilinear ones by the grid engine, any other "
            "bounded by straight edges by the general engine); used by the AutoBlock workbench.";

  py::register_local_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const py::error_already_set&) {
      throw;
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Standard_Failure& e) {
      PyErr_SetString(PyExc_RuntimeError, (std::string("OpenCASCADE failed: ") + e.GetMessageString()).c_str());
    } catch (const std::exception& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  m.def("version", [] { return std::string(AUTOBLOCK_VERSION); }, "The AutoBlock version this module was built from.");
  m.def("capabilities", &capabilities_dict,
        "What this build can do beyond the baselines: {'learned_policies', 'training', 'vertex_scores', 'meshing'}.");
  m.def("policy_names", [] { return policy_names(); }, "The shipped policy names.");
  m.def("default_policy", &default_policy_name, "The policy used when none is named.");
  m.def("reward_presets", [] { return reward_preset_names(); }, "The reward presets.");
  m.def("default_reward_preset", &default_reward_preset, "The default reward preset.");
  m.def("block_colours", &block_colours, py::arg("count"),
        "Distinct pastel colours (r, g, b in [0, 1]) for blocks 0 .. count-1, as in the SVG pictures.");
  m.def("format_number", [](double value, double tolerance) { return format_number(value, tolerance); },
        py::arg("value"), py::arg("tolerance") = 0.0,
        "A number as messages print it: a plain decimal ('80', '2.5') rounded to `tolerance` (noise below it reads "
        "'0'; 0: exact), scientific notation only beyond 1e15 or below 1e-4.");
  m.def("face_frame", &face_frame_py, py::arg("brep"),
        "The face's own frame by the core's rule (the one the CLI uses) as 12 numbers: row-major rotation, then "
        "translation; the identity for a face parallel to XY that is rectilinear there or general, or for text "
        "holding no single face.");
  m.def("check_face", &check_face_py, py::arg("brep"), py::arg("source") = "face",
        "Validate the single planar face held by BREP text. Returns its figures; raises ValueError saying what is "
        "wrong and where.");
  m.def("decompose", &decompose_py, py::arg("brep"), py::arg("policy") = "", py::arg("reward") = "",
        py::arg("seed") = 0, py::arg("time_limit") = 30.0, py::arg("max_steps") = 0, py::arg("source") = "face",
        py::arg("general_time_limit") = -1.0,
        "Decompose the face held by BREP text into blocks. policy: a name of policy_names() ('' for the default); "
        "reward: a preset ('' for the default); time_limit: the grid engine's search budget; general_time_limit: the "
        "general engine's (< 0: the core's default). Returns a dict: engine ('grid' or 'general'), blocks (BREP "
        "text each), shape (BREP text of their compound), cuts, return, n_blocks, min_blocks, status, ...; a grid "
        "face's cuts are {part, vertex, direction, ...} with boxes; a general face's dict is the CLI's JSON report "
        "(cuts {part, kind, origin, direction, forced, chords, ...}, outlines, n_templates, min_blocks None).");
  m.def("step", &step_py, py::arg("brep"), py::arg("cuts"), py::arg("step"), py::arg("max_steps") = 0,
        py::arg("reward") = "paper", py::arg("source") = "face", py::arg("rules") = std::vector<double>{},
        "The episode of a cut sequence on the face after `step` cuts, rewards under the preset `reward` (the "
        "decomposition's 'reward'): pieces (polygons), blocks, return, and the next cut (part, vertices, chosen vertex, "
        "line, reward) or None. Cuts: [(part, x, y, 'horizontal'|'vertical'), ...] on a grid face, [(part, kind, ox, "
        "oy, dx, dy, forced), ...] on a general face (kind 'full', 'partial' or 'template'; then the next cut also "
        "has kind, origin, direction (a vector) and its chords as line, chosen -1 when the origin is on an edge). "
        "rules: a general sequence's block rules, [min corner, max corner, flat tolerance] in degrees as its "
        "decomposition's 'rules' give them ([]: the face's own, as a search makes them).");
  m.def("replay", &replay_py, py::arg("brep"), py::arg("cuts"), py::arg("max_steps") = 0, py::arg("reward") = "paper",
        py::arg("policy") = "replay", py::arg("source") = "face", py::arg("rules") = std::vector<double>{},
        py::arg("min_edge_intervals") = 1,
        "Replay a general face's cut sequence [(part, kind, ox, oy, dx, dy, forced), ...] (as step() takes it) "
        "without searching again: the same dict as decompose() gives for a general face (policy: the name it "
        "reports; rules and min_edge_intervals: the decomposition's, as step() and mesh() take them, reported "
        "back). ValueError when an action does not belong to the face, the sequence leaves parts unfinished, "
        "or the face is rectilinear.");
  m.def("policy_info", &policy_info_py, py::arg("policy") = "",
        "What a policy is: {'name', 'learned' (a trained policy with a value network), 'reward' (the preset it "
        "aims at: a trained policy's own), 'scores_by', 'general_network' (a second network decides on general "
        "faces)}. policy: a name or a policy file ('' for the default).");
  m.def("combine_policies", &combine_policies_py, py::arg("grid"), py::arg("general"), py::arg("output"),
        "Write output, one policy file with grid's network for rectilinear faces and general's for the others "
        "(shipped names or policy files). Returns the file's meta (JSON text). ValueError for unreadable files, "
        "different reward presets or a missing folder.");
  m.def("vertex_scores", &vertex_scores_py, py::arg("brep"), py::arg("cuts"), py::arg("step"), py::arg("policy") = "",
        py::arg("max_steps") = 0, py::arg("reward") = "paper", py::arg("source") = "face",
        py::arg("rules") = std::vector<double>{},
        "The policy's value-network score at every vertex of the part cut after `step` cuts, in the order of "
        "step()['next']['vertices'] (-inf where no candidate cut runs through the vertex; on a general face, where "
        "none of the policy's shortlisted actions starts). ValueError for a baseline policy (no value network), the "
        "paper's agent on a general face, or a step with no cut. rules: a general sequence's block rules, as step.");
  m.def("mesh", &mesh_py, py::arg("brep"), py::arg("cuts"), py::arg("size") = 0.0, py::arg("max_steps") = 0,
        py::arg("reward") = "paper", py::arg("out") = "", py::arg("placement") = std::vector<double>{},
        py::arg("source") = "face", py::arg("rules") = std::vector<double>{}, py::arg("min_edge_intervals") = 1,
        "Mesh the decomposition given by its cut sequence with quads (size: target element size, 0 for automatic). "
        "Returns nodes [(x, y, z)] in the face's frame, quads [(a, b, c, d)] (0-based, counter-clockwise), "
        "quad_block, blocks, target_size, quality, conformal. out: also write a .msh, .vtu or .inp file, its nodes "
        "moved by placement (12 numbers: row-major rotation, translation; [] for none). A general face's rules and "
        "min_edge_intervals: its decomposition's (as step() takes them; at least that many intervals on every "
        "model edge).");
  m.def("check_solid", &check_solid_py, py::arg("brep"), py::arg("source") = "solid",
        "Check that BREP text holds a straight sweep of a planar face (one solid, or a closed shell). Returns "
        "{source, caps (bottom, top face numbers, 1-based), sweep (x, y, z), volume, area, faces}; raises "
        "ValueError saying why not (naming the face).");
  m.def("mesh_solid", &mesh_solid_py, py::arg("brep"), py::arg("policy") = "", py::arg("reward") = "",
        py::arg("seed") = 0, py::arg("time_limit") = 30.0, py::arg("max_steps") = 0, py::arg("size") = 0.0,
        py::arg("layers") = 0, py::arg("grading") = 1.0, py::arg("blocks") = true, py::arg("source") = "solid",
        py::arg("general_time_limit") = -1.0, py::arg("out") = "", py::arg("element") = "C3D8",
        "Mesh the swept solid held by BREP text with hexahedra: its bottom cap decomposed (policy, reward, seed, "
        "time_limit, max_steps, general_time_limit as for decompose) and quad-meshed at size (0: the solid's "
        "longest side / 20), swept in layers (0: from the size) graded by grading. Returns check_solid's dict and "
        "nodes [(x, y, z)] (model coordinates), hexes [(8 node indices, 0-based, C3D8 order)], hex_block, "
        "n_blocks, layers, policy, target_size, quality, conformal, problem, hex_volume, and (blocks True) the "
        "prism blocks as BREP text (blocks, one solid each; shape, their compound sharing faces); cap: the cap's "
        "decomposition as decompose returns a face's (engine, policy, reward, cuts, return, n_blocks, status, ...; "
        "no blocks), with brep (the cap in its frame), frame (12 numbers, as face_frame) and face_number. out: also write the "
        "hexahedra to a .msh, .vtu or .inp file (element: C3D8 or C3D8I for .inp), as `autoblock mesh SOLID --out`.");
  m.def("train", &train_py, py::arg("options"), py::arg("progress") = py::none(),
        "Train a policy (blocking, the GIL released). options: {output, checkpoint, resume, train_folder | "
        "train_generate {count, seed, min_rects, max_rects, holes, general, arcs}, test_folder | test_generate, episodes, seed, "
        "reward, agent, threads, eval_every, max_steps}. progress(event) is called with the GIL after every "
        "episode (event: episode, episodes, return, blocks, steps, complete, shape, seconds, test_return or None, "
        "earlier), and before the first with {status, episodes} (what the run computes first), and returns False to stop. Returns {cancelled, episodes_done, episodes, reward, policy_file (None "
        "when cancelled), checkpoint, log, curves, final_test_return}.");
}
