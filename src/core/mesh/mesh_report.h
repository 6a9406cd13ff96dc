// The JSON report of one meshed face (the `autoblock mesh --json` contract).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/env/decomposition.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/region/region_policy.h"

namespace autoblock {

// Inputs:  input, the file name; decomposition; result; seconds, the whole run's wall time
//          (decomposition and meshing, no file I/O).
// Outputs: {"input", "policy", "blocks", "nodes", "quads", "target_size", "default_size",
//          "intervals": {"strips", "max_deviation", "max_relative_deviation",
//                        "mean_relative_deviation", "optimal", "fixed"},
//          "quality": {"min_scaled_jacobian", "mean_scaled_jacobian", "max_aspect_ratio",
//                      "mean_aspect_ratio", "max_skew", "min_angle", "max_angle",
//                      "interior_vertices", "irregular_interior_vertices"},
//          "conformal", "conformity": {"interior_edges", "boundary_edges", "overused_edges",
//                      "stray_boundary_edges", "misoriented_edges", "inverted_quads", "quad_area", "face_area",
//                      "boundary_length", "face_perimeter", "problem"},
//          "seconds", "timing": {"decomposition", "merge", "intervals", "mesh", "checks"},
//          "decomposition": {"complete", "min_blocks", "cuts", "return", "time_capped",
//          "decided_by": {policy: cuts it chose}}}
nlohmann::json mesh_report_json(const std::string& input, const Decomposition& decomposition, const MeshResult& result,
                                double seconds);

// Inputs:  input; decomposition, a general face's; result (mesh_region_decomposition's); seconds.
// Outputs: the report above, with "intervals": {"edges" (model edges) instead of "strips", ...},
//          "quality" adding "bound" (scaled_jacobian_bound), "min_scaled_jacobian_over_bound",
//          "topology_bound" (topology_jacobian_bound) and "min_scaled_jacobian_over_topology_bound",
//          "blocks" counting the finished parts and "templates" those finished by a template,
//          "two_corner_templates" (true when the mesh kept was made with the two-corner template
//          where it beats the smooth one: MeshResult::two_corner), "intervals" adding "arc_targets",
//          "smoothing": {"sweeps", "moves", "min_scaled_jacobian_before"} (mesh_smoothing.h), and
//          "decomposition": {"complete", "cuts", "return", "time_capped", "policy_steps", "work"}.
nlohmann::json mesh_report_json(const std::string& input, const RegionDecomposition& decomposition,
                                const MeshResult& result, double seconds);

}  // namespace autoblock
