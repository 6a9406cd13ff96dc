#include "core/io/decomposition_json.h"

#include <cmath>

#include "core/geometry/part_boundary.h"

namespace autoblock {
namespace {

nlohmann::json point_json(double x, double y) { return nlohmann::json::array({x, y}); }

nlohmann::json box_json(const Box& b) {
  return nlohmann::json::array({point_json(b.xmin, b.ymin), point_json(b.xmax, b.ymin), point_json(b.xmax, b.ymax),
                                point_json(b.xmin, b.ymax)});
}

}  // namespace

nlohmann::json decomposition_json(const std::string& input, const PlanarFace& face, const Decomposition& d) {
  nlohmann::json report;
  report["input"] = input;
  report["policy"] = d.policy;
  report["reward"] = reward_preset_name(d.reward);
  report["blocks"] = nlohmann::json::array();
  for (const Box& b : d.blocks) report["blocks"].push_back(box_json(b));
  report["cuts"] = nlohmann::json::array();
  nlohmann::json deciders = nlohmann::json::object();
  for (size_t k = 0; k < d.cuts.size(); ++k) {
    const CutRecord& c = d.cuts[k];
    nlohmann::json cut{{"part", c.part_id},
                       {"vertex", point_json(c.position.x, c.position.y)},
                       {"direction", direction_name(c.direction)},
                       {"n_parts", c.n_parts},
                       {"reward", c.reward}};
    if (k < d.decided_by.size()) {
      cut["decided_by"] = d.decided_by[k];
      deciders[d.decided_by[k]] = deciders.value(d.decided_by[k], 0) + 1;
    }
    report["cuts"].push_back(cut);
  }
  report["decided_by"] = deciders;  // cuts per deciding policy (auto: optimal and the learned policy)
  report["return"] = d.total_return;
  report["n_blocks"] = d.blocks.size();
  report["min_blocks"] = d.min_blocks;
  report["complete"] = d.complete();
  report["truncated"] = d.truncated();
  report["seconds"] = d.seconds;
  report["status"] = status_name(d.status);
  report["time_capped"] = d.time_capped;
  report["steps"] = d.cuts.size();
  report["unfinished"] = nlohmann::json::array();
  for (const Part& part : d.unfinished) {
    nlohmann::json loops = nlohmann::json::array();
    for (const CornerRing& loop : part_boundary(part)) {
      nlohmann::json ring = nlohmann::json::array();
      for (const Corner& c : loop) {
        ring.push_back(point_json(part.grid().xs[static_cast<size_t>(c.i)], part.grid().ys[static_cast<size_t>(c.j)]));
      }
      loops.push_back(ring);
    }
    report["unfinished"].push_back(loops);
  }
  const Box box = ring_bbox(face.polygon.outer);
  size_t corners = face.polygon.outer.size();
  for (const Ring& hole : face.polygon.holes) corners += hole.size();
  report["face"] = {{"z", face.z},
                    {"area", polygon_area(face.polygon)},
                    {"corners", corners},
                    {"holes", face.polygon.holes.size()},
                    {"bbox", {box.xmin, box.ymin, box.xmax, box.ymax}}};
  return report;
}

nlohmann::json frame_json(const Placement& frame) {
  return {{"rotation", frame.rotation}, {"translation", frame.translation}, {"identity", frame.identity()}};
}

nlohmann::json region_decomposition_json(const std::string& input, const InputFace& face, const RegionDecomposition& d) {
  auto loop_json = [](const Ring& ring) {
    nlohmann::json out = nlohmann::json::array();
    for (const Point2& p : ring) out.push_back(point_json(p.x, p.y));
    return out;
  };
  auto region_loops = [&](const Region& r) {
    nlohmann::json loops = nlohmann::json::array();
    for (int k = 0; k < r.loop_count(); ++k) loops.push_back(loop_json(r.loop(k)));
    return loops;
  };
  nlohmann::json report;
  report["input"] = input;
  report["engine"] = "general";
  report["policy"] = d.policy;
  report["reward"] = reward_preset_name(d.reward);
  report["blocks"] = nlohmann::json::array();
  for (const FinishedRegion& f : d.finished) {
    nlohmann::json block{{"outline", loop_json(f.region.outer())}, {"template", f.is_template}};
    block["corners"] = f.is_template ? nlohmann::json::array() : nlohmann::json(f.corners);
    report["blocks"].push_back(block);
  }
  report["cuts"] = nlohmann::json::array();
  for (const RegionCutRecord& c : d.cuts) {
    nlohmann::json cut{{"part", c.part_id}, {"kind", action_kind_name(c.action)}, {"n_parts", c.n_parts}, {"reward", c.reward},
                       {"children", c.children}};
    if (c.action.kind == RegionAction::Kind::Cut) {
      const RegionCut& rc = c.action.cut;
      cut["origin"] = point_json(rc.origin.x, rc.origin.y);
      cut["direction"] = point_json(rc.direction.x, rc.direction.y);
      cut["angle_degrees"] = std::atan2(rc.direction.y, rc.direction.x) * 180.0 / M_PI;
      cut["forced"] = rc.forced;  // taken by the engine's last resort (region_cut.h): a replay needs it
      cut["chords"] = nlohmann::json::array();
      for (const Chord& chord : c.chords) cut["chords"].push_back({point_json(chord.a.x, chord.a.y), point_json(chord.b.x, chord.b.y)});
    }
    report["cuts"].push_back(cut);
  }
  report["return"] = d.total_return;
  report["n_blocks"] = d.blocks;
  report["n_templates"] = d.templates;
  report["complete"] = d.complete();
  report["truncated"] = d.status == EpisodeStatus::Truncated;
  report["status"] = status_name(d.status);
  report["time_capped"] = d.time_capped;
  report["steps"] = d.cuts.size();
  report["policy_steps"] = d.policy_steps;
  report["work"] = d.work;
  report["seconds"] = d.seconds;
  if (!d.fallback_from.empty()) report["policy_fallback"] = {{"policy", d.fallback_from}, {"reason", d.fallback_reason}};
  // What a replay needs besides the cuts: the block rules they were made under, and the mesh's edges.
  report["rules"] = {{"min_corner_degrees", d.rules.min_corner_degrees},
                     {"max_corner_degrees", d.rules.max_corner_degrees},
                     {"flat_tolerance_degrees", d.rules.flat_tolerance_degrees}};
  report["min_edge_intervals"] = d.min_edge_intervals;
  report["unfinished"] = nlohmann::json::array();
  for (const Region& part : d.unfinished) report["unfinished"].push_back(region_loops(part));
  const Region& r = face.region;
  const Box box = r.bbox();
  report["face"] = {{"z", face.planar.z},
                    {"area", r.area()},
                    {"corners", r.vertex_count()},
                    {"holes", r.holes().size()},
                    {"bbox", {box.xmin, box.ymin, box.xmax, box.ymax}},
                    {"loops", region_loops(r)}};
  report["frame"] = frame_json(face.frame);
  return report;
}

}  // namespace autoblock
