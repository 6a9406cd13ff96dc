// The JSON report of one decomposition (the `autoblock decompose --json` contract).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/env/decomposition.h"
#include "core/geometry/planar_face.h"

namespace autoblock {

// Inputs:  input, the file name; face, the validated face; decomposition.
// Outputs: {"input", "policy", "blocks": [[[x,y] x 4 counter-clockwise], ...], "cuts": [{"part",
//          "vertex": [x,y], "direction", "n_parts", "reward"}], "return", "n_blocks",
//          "min_blocks", "complete", "truncated", "seconds"} plus "reward" (the preset), "status", "steps",
//          "unfinished" (corner loops of parts left when truncated) and "face" (z, area, corners,
//          holes, bounding box).
nlohmann::json decomposition_json(const std::string& input, const PlanarFace& face, const Decomposition& decomposition);

}  // namespace autoblock
