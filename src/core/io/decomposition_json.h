// The JSON report of one decomposition (the `autoblock decompose --json` contract).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/env/decomposition.h"
#include "core/geometry/planar_face.h"
#include "core/io/input_face.h"
#include "core/region/region_policy.h"

namespace autoblock {

// Inputs:  input, the file name; face, the validated face; decomposition.
// Outputs: {"input", "policy", "blocks": [[[x,y] x 4 counter-clockwise], ...], "cuts": [{"part",
//          "vertex": [x,y], "direction", "n_parts", "reward"}], "return", "n_blocks",
//          "min_blocks", "complete", "truncated", "seconds"} plus "reward" (the preset), "status", "steps",
//          "unfinished" (corner loops of parts left when truncated) and "face" (z, area, corners,
//          holes, bounding box).
nlohmann::json decomposition_json(const std::string& input, const PlanarFace& face, const Decomposition& decomposition);

// Inputs:  input, the file name; face, the checked face; decomposition, the general engine's.
// Outputs: {"input", "engine": "general", "policy", "reward", "blocks": [{"outline": [[x,y], ...]
//          counter-clockwise, "corners": [i,j,k,l] (indices into outline; empty for a template),
//          "template": bool}, ...], "cuts": [{"part", "kind" (full, partial, template), "n_parts",
//          "reward", "children" (the pieces' ids), and for a cut "origin": [x,y], "direction": [dx,dy],
//          "angle_degrees", "forced", "chords": [[[x,y],[x,y]], ...]}], "return", "n_blocks",
//          "n_templates", "complete", "truncated", "status", "time_capped", "steps", "policy_steps", "work",
//          "seconds", "rules" ({"min_corner_degrees", "max_corner_degrees", "flat_tolerance_degrees"}: the
//          block rules the cuts were made under, which a replay needs), "min_edge_intervals" (what its
//          mesh was judged with, RegionDecomposition), "unfinished" (loops of parts left), "face",
//          and "policy_fallback": {"policy", "reason"} when the policy asked for gave blocks that do
//          not mesh and these are the search's (RegionDecomposition::fallback_from)}.
//          Coordinates are the face's frame's (see "frame").
nlohmann::json region_decomposition_json(const std::string& input, const InputFace& face,
                                         const RegionDecomposition& decomposition);

// Inputs: frame. Output: {"rotation": [9 numbers, row-major], "translation": [x,y,z], "identity": bool}:
//         a point (x, y, z) of the report is the model's point rotation (x, y, z) + translation.
nlohmann::json frame_json(const Placement& frame);

}  // namespace autoblock
