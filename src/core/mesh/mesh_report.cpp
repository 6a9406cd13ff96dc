#include "core/mesh/mesh_report.h"

namespace autoblock {

namespace {

// The fields every report has; the decomposition's and the counting unit's come from the callers.
nlohmann::json common_report(const std::string& input, const std::string& policy, size_t blocks, const MeshResult& r,
                             double seconds, const char* unit, size_t units, double decomposition_seconds) {
  const MeshQuality& q = r.quality;
  const Conformity& c = r.conformity;
  nlohmann::json report;
  report["input"] = input;
  report["policy"] = policy;
  report["blocks"] = blocks;
  report["nodes"] = r.mesh.nodes.size();
  report["quads"] = r.mesh.quads.size();
  report["target_size"] = r.intervals.target_size;
  report["default_size"] = r.default_size;
  report["intervals"] = {{unit, units},
                         {"max_deviation", r.intervals.max_deviation},
                         {"max_relative_deviation", r.intervals.max_relative_deviation},
                         {"mean_relative_deviation", r.intervals.mean_relative_deviation},
                         {"optimal", r.intervals.optimal},
                         {"fixed", nlohmann::json::array()}};
  for (const FixedIntervals& f : r.fixed) {
    report["intervals"]["fixed"].push_back({{"edge", f.what}, {"intervals", f.intervals}, {unit, f.strips.size()}});
  }
  report["quality"] = {{"min_scaled_jacobian", q.min_scaled_jacobian},
                       {"mean_scaled_jacobian", q.mean_scaled_jacobian},
                       {"max_aspect_ratio", q.max_aspect_ratio},
                       {"mean_aspect_ratio", q.mean_aspect_ratio},
                       {"max_skew", q.max_skew},
                       {"min_angle", q.min_angle},
                       {"max_angle", q.max_angle},
                       {"interior_vertices", q.interior_nodes},
                       {"irregular_interior_vertices", q.irregular_interior_nodes},
                       {"bound", r.bound},
                       {"min_scaled_jacobian_over_bound", q.min_scaled_jacobian / r.bound},
                       {"topology_bound", r.topology_bound},
                       {"min_scaled_jacobian_over_topology_bound", q.min_scaled_jacobian / r.topology_bound}};
  report["conformal"] = c.conformal;
  report["conformity"] = {{"interior_edges", c.interior_edges},     {"boundary_edges", c.boundary_edges},
                          {"overused_edges", c.overused_edges},     {"stray_boundary_edges", c.stray_boundary_edges},
                          {"misoriented_edges", c.misoriented_edges},
                          {"inverted_quads", c.inverted_quads},     {"quad_area", c.quad_area},
                          {"face_area", c.face_area},               {"boundary_length", c.boundary_length},
                          {"face_perimeter", c.face_perimeter},     {"curved_gap_area", c.curved_gap_area},
                          {"problem", c.problem}};
  report["seconds"] = seconds;
  report["timing"] = {{"decomposition", decomposition_seconds},
                      {"merge", r.merge_seconds},
                      {"intervals", r.interval_seconds},
                      {"mesh", r.mesh_seconds},
                      {"checks", r.check_seconds}};
  return report;
}

}  // namespace

nlohmann::json mesh_report_json(const std::string& input, const Decomposition& d, const MeshResult& r, double seconds) {
  nlohmann::json report =
      common_report(input, d.policy, d.blocks.size(), r, seconds, "strips", r.layout.strips.size(), d.seconds);
  nlohmann::json deciders = nlohmann::json::object();
  for (const std::string& who : d.decided_by) deciders[who] = deciders.value(who, 0) + 1;
  report["decomposition"] = {{"complete", d.complete()},         {"min_blocks", d.min_blocks},
                             {"cuts", d.cuts.size()},            {"return", d.total_return},
                             {"time_capped", d.time_capped},     {"decided_by", deciders}};
  return report;
}

nlohmann::json mesh_report_json(const std::string& input, const RegionDecomposition& d, const MeshResult& r,
                                double seconds) {
  nlohmann::json report = common_report(input, d.policy, d.finished.size(), r, seconds, "edges",
                                        r.block_model.edges.size(), d.seconds);
  report["templates"] = d.templates;
  report["intervals"]["arc_targets"] = r.arc_targets;
  report["two_corner_templates"] = r.two_corner;
  report["acute_tips"] = r.acute_tips;
  report["feet_snapped"] = r.block_model.snapped_feet > 0;  // the kept model's (block_model's snap)
  report["far_feet"] = r.block_model.far_feet();
  report["wide_tolerance"] = r.wide_tolerance;
  report["smoothing"] = {{"sweeps", r.smoothing.sweeps},
                         {"moves", r.smoothing.moves},
                         {"min_scaled_jacobian_before", r.smoothing.min_before}};
  report["decomposition"] = {{"complete", d.complete()},     {"cuts", d.cuts.size()},
                             {"return", d.total_return},     {"time_capped", d.time_capped},
                             {"policy_steps", d.policy_steps}, {"work", d.work}};
  return report;
}

}  // namespace autoblock
