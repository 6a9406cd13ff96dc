#include "core/io/decomposition_json.h"

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

}  // namespace autoblock
