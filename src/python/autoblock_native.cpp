// autoblock_native: the AutoBlock core for Python (FreeCAD's Python 3.11), deliberately thin.
//
// Every function converts its inputs, calls one entry point of core/api (face_actions.h,
// catalog.h) with the GIL released, and converts the result. Shapes cross as BREP text (FreeCAD:
// shape.exportBrepToString() / Part.Shape().importBrepFromString()); everything else as str, int,
// float, tuple, list and dict. No C++ type is registered with pybind11: FreeCAD's own pybind11
// modules share pybind11's internals with this one.
//
// Errors: autoblock::InputError (the user's input is wrong) -> ValueError; any other failure
// (std::exception, OpenCASCADE's Standard_Failure) -> RuntimeError.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Standard_Failure.hxx>

#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "core/api/face_actions.h"
#include "core/baselines/min_rectangles.h"
#include "core/common/error.h"
#include "core/io/shape_file.h"
#include "core/io/svg_picture.h"

namespace py = pybind11;
using namespace autoblock;

namespace {

// The face held by BREP text (exactly one face), checked.
InputFace face_of(const std::string& brep, const std::string& source) {
  const TopoDS_Shape shape = read_brep_text(brep);
  return check_face(single_face(shape, source), source);
}

CutDirection direction_of(const std::string& name) {
  if (name == "horizontal") return CutDirection::Horizontal;
  if (name == "vertical") return CutDirection::Vertical;
  throw InputError("unknown cut direction '" + name + "' (expected horizontal or vertical)");
}

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
  const RectilinearPolygon& polygon = face.planar.polygon;
  size_t corners = polygon.outer.size();
  for (const Ring& hole : polygon.holes) corners += hole.size();
  const Box box = ring_bbox(polygon.outer);
  d["source"] = face.source;
  d["z"] = face.planar.z;
  d["normal_up"] = face.planar.normal_up;
  d["corners"] = corners;
  d["holes"] = polygon.holes.size();
  d["area"] = polygon_area(polygon);
  d["bbox"] = py::make_tuple(box.xmin, box.ymin, box.xmax, box.ymax);
  d["outer"] = ring_list(polygon.outer);
  py::list holes;
  for (const Ring& hole : polygon.holes) holes.append(ring_list(hole));
  d["hole_rings"] = holes;
  return d;
}

py::dict check_face_py(const std::string& brep, const std::string& source) {
  InputFace face;
  int minimum = 0;
  {
    py::gil_scoped_release release;
    face = face_of(brep, source);
    minimum = min_rectangles(face.grid.whole);
  }
  py::dict d = face_dict(face);
  d["min_blocks"] = minimum;
  return d;
}

py::dict decompose_py(const std::string& brep, const std::string& policy, const std::string& reward, std::uint64_t seed,
                      double time_limit, int max_steps, const std::string& source) {
  DecomposeSettings settings;
  if (!policy.empty()) settings.policy = policy;
  if (!reward.empty()) settings.reward = reward;
  settings.policy_settings.seed = seed;
  settings.policy_settings.time_limit = time_limit;
  settings.max_steps = max_steps;
  FaceDecomposition result;
  std::vector<std::string> blocks;
  std::string shape;
  {
    py::gil_scoped_release release;
    result = decompose_input_face(face_of(brep, source), settings);
    for (const TopoDS_Face& block : result.block_faces) blocks.push_back(write_brep_text(block));
    shape = write_brep_text(result.shape);
  }
  const Decomposition& d = result.decomposition;
  py::dict out;
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

py::dict step_py(const std::string& brep, const std::vector<std::tuple<int, double, double, std::string>>& cuts, int step,
                 int max_steps, const std::string& reward, const std::string& source) {
  const RewardPreset preset = reward_preset_by_name(reward);
  std::vector<CutSpec> specs;
  for (const auto& [part, x, y, direction] : cuts) specs.push_back(CutSpec{part, Point2{x, y}, direction_of(direction)});
  InputFace face;
  EpisodeSnapshot s;
  {
    py::gil_scoped_release release;
    face = face_of(brep, source);
    s = face_step(face, specs, step, max_steps, preset);
  }
  py::dict out;
  out["step"] = s.step;
  out["steps"] = s.steps;
  out["blocks"] = s.blocks;
  out["return"] = s.return_so_far;
  out["status"] = status_name(s.status);
  out["z"] = face.planar.z;
  out["normal_up"] = face.planar.normal_up;
  py::list pieces;
  for (const SnapshotPiece& piece : s.pieces) {
    py::dict p;
    p["id"] = piece.id;
    p["block"] = piece.block;
    p["outer"] = ring_list(piece.polygon.outer);
    py::list holes;
    for (const Ring& hole : piece.polygon.holes) holes.append(ring_list(hole));
    p["holes"] = holes;
    pieces.append(p);
  }
  out["pieces"] = pieces;
  if (s.has_next) {
    py::dict next;
    next["part"] = s.current_part_id;
    py::list vertices;
    for (const Point2& v : s.vertices) vertices.append(xy(v));
    next["vertices"] = vertices;
    next["chosen"] = s.chosen_vertex;
    next["vertex"] = xy(s.vertices[static_cast<size_t>(s.chosen_vertex)]);
    next["direction"] = direction_name(s.direction);
    py::list line;
    for (const Segment& segment : s.line) line.append(py::make_tuple(xy(segment.a), xy(segment.b)));
    next["line"] = line;
    next["reward"] = s.reward;
    next["n_parts"] = s.n_parts;
    out["next"] = next;
  } else {
    out["next"] = py::none();
  }
  return out;
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
  m.doc() = "The AutoBlock core (block decomposition of planar rectilinear faces); used by the AutoBlock workbench.";

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
  m.def("check_face", &check_face_py, py::arg("brep"), py::arg("source") = "face",
        "Validate the single planar face held by BREP text. Returns its figures; raises ValueError saying what is "
        "wrong and where.");
  m.def("decompose", &decompose_py, py::arg("brep"), py::arg("policy") = "", py::arg("reward") = "",
        py::arg("seed") = 0, py::arg("time_limit") = 30.0, py::arg("max_steps") = 0, py::arg("source") = "face",
        "Decompose the face held by BREP text into rectangular blocks. policy: a name of policy_names() ('' for the "
        "default); reward: a preset ('' for the default). Returns a dict: blocks (BREP text each), shape (BREP text "
        "of their compound), boxes, cuts, return, n_blocks, min_blocks, status, ...");
  m.def("step", &step_py, py::arg("brep"), py::arg("cuts"), py::arg("step"), py::arg("max_steps") = 0,
        py::arg("reward") = "paper", py::arg("source") = "face",
        "The episode of a cut sequence [(part, x, y, 'horizontal'|'vertical'), ...] on the face after `step` cuts, "
        "rewards under the preset `reward` (the decomposition's 'reward'): "
        "pieces (polygons), blocks, return, and the next cut (part, vertices, chosen vertex, line, reward) or None.");
}
