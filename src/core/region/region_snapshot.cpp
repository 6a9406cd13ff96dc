#include "core/region/region_snapshot.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/region/block.h"

namespace autoblock {

std::vector<RegionActionSpec> region_action_specs(const std::vector<RegionCutRecord>& records) {
  std::vector<RegionActionSpec> specs;
  specs.reserve(records.size());
  for (const RegionCutRecord& r : records) specs.push_back({r.part_id, r.action});
  return specs;
}

RegionAction region_action_of_kind(const std::string& name) {
  RegionAction action;
  if (name == "template") {
    action.kind = RegionAction::Kind::Template;
  } else if (name == "full" || name == "partial") {
    action.cut.kind = name == "full" ? CutKind::Full : CutKind::Partial;
  } else {
    throw InputError("unknown action kind '" + name + "' (expected full, partial or template)");
  }
  return action;
}

namespace {

// The distance from point to the nearest edge of region's loops.
double boundary_distance(const Region& region, Point2 point) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < region.loop_count(); ++k) {
    const Ring& ring = region.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) best = std::min(best, segment_distance(point, ring[i], ring[(i + 1) % ring.size()]));
  }
  return best;
}

// Throws InputError when `spec`, the action number `index` (0-based), does not belong to the episode's current part.
void check_action(const RegionEpisode& episode, const RegionActionSpec& spec, size_t index) {
  const std::string which = "action " + std::to_string(index + 1);
  const Region& part = episode.current_part();
  const double q = part.quantum();
  if (spec.part_id != episode.current_part_id()) {
    throw InputError("the sequence does not belong to this face: " + which + " cuts part " + std::to_string(spec.part_id) +
                     ", but the part to cut then is " + std::to_string(episode.current_part_id()));
  }
  if (spec.action.kind == RegionAction::Kind::Template) {
    if (!template_applies(part)) {
      throw InputError("the sequence does not belong to this face: " + which + " finishes part " +
                       std::to_string(spec.part_id) + " with a template, which needs a convex part or one with a round hole (the O-grid)");
    }
    return;
  }
  const RegionCut& cut = spec.action.cut;
  const Point2 o = cut.origin, d = cut.direction;
  if (!std::isfinite(o.x) || !std::isfinite(o.y) || !std::isfinite(d.x) || !std::isfinite(d.y) ||
      std::hypot(d.x, d.y) <= 0.0) {
    throw InputError(which + ": a cut needs a finite origin and a finite, non-zero direction");
  }
  const double off = boundary_distance(part, o);
  if (off > 2.0 * q) {
    throw InputError("the sequence does not belong to this face: " + which + " starts at " + format_point(o.x, o.y, q) +
                     ", " + format_number(off, q) + " away from the boundary of part " + std::to_string(spec.part_id));
  }
}

RegionEpisodeOptions replay_options(RegionEpisodeOptions options, const Region& face, size_t actions) {
  if (options.max_steps <= 0) options.max_steps = 10 * face.vertex_count() + 10;
  options.max_steps = std::max(options.max_steps, static_cast<int>(actions));
  return options;
}

}  // namespace

RegionEpisode replay_region_episode(const Region& face, const std::vector<RegionActionSpec>& actions, int step,
                                    RegionEpisodeOptions options) {
  if (step < 0 || step > static_cast<int>(actions.size())) {
    throw InputError("step " + std::to_string(step) + " is out of range: the sequence has " +
                     counted(static_cast<long long>(actions.size()), "action") + " (steps 0 to " +
                     std::to_string(actions.size()) + ")");
  }
  RegionEpisode episode(face, replay_options(options, face, actions.size()));
  for (size_t i = 0; i < static_cast<size_t>(step); ++i) {
    if (!episode.running()) {
      throw InputError("the sequence does not belong to this face: every part is finished after " +
                       counted(static_cast<long long>(i), "action") + ", but it has " +
                       std::to_string(actions.size()));
    }
    check_action(episode, actions[i], i);
    episode.step(actions[i].action);
  }
  return episode;
}

RegionSnapshot region_snapshot(const Region& face, const std::vector<RegionActionSpec>& actions, int step,
                               RegionEpisodeOptions options) {
  RegionEpisode episode = replay_region_episode(face, actions, step, options);
  RegionSnapshot s;
  s.step = step;
  s.steps = static_cast<int>(actions.size());
  for (const FinishedRegion& f : episode.finished()) {
    s.pieces.push_back({f.id, true, f.is_template, f.region});
    (f.is_template ? s.templates : s.blocks) += 1;
  }
  for (const RegionPiece& p : episode.queue()) s.pieces.push_back({p.id, false, false, p.region});
  s.return_so_far = episode.total_return();
  s.status = episode.status();
  if (step < s.steps) {
    if (!episode.running()) {
      throw InputError("the sequence does not belong to this face: every part is finished after " +
                       counted(step, "action") + ", but it has " + std::to_string(s.steps));
    }
    const RegionActionSpec& next = actions[static_cast<size_t>(step)];
    check_action(episode, next, static_cast<size_t>(step));
    const Region& part = episode.current_part();
    s.has_next = true;
    s.current_part_id = episode.current_part_id();
    for (int k = 0; k < part.loop_count(); ++k) {
      for (const Point2& v : part.loop(k)) s.vertices.push_back(v);
    }
    s.action = next.action;
    if (next.action.kind == RegionAction::Kind::Cut) {
      const double q = part.quantum();
      for (size_t i = 0; i < s.vertices.size(); ++i) {
        if (std::hypot(s.vertices[i].x - next.action.cut.origin.x, s.vertices[i].y - next.action.cut.origin.y) <= q) {
          s.chosen_vertex = static_cast<int>(i);
          break;
        }
      }
    }
    const RegionCutRecord& record = episode.step(next.action);
    s.chords = record.chords;
    s.reward = record.reward;
    s.n_parts = record.n_parts;
  }
  return s;
}

RegionDecomposition replay_region_decomposition(const Region& face, const std::vector<RegionActionSpec>& actions,
                                                RegionEpisodeOptions options, const std::string& policy) {
  const auto start = std::chrono::steady_clock::now();
  const RegionEpisode episode = replay_region_episode(face, actions, static_cast<int>(actions.size()), options);
  if (episode.running() || !episode.queue().empty()) {
    throw InputError("the sequence ends after " + counted(static_cast<long long>(actions.size()), "action") + " with " +
                     counted(static_cast<long long>(episode.queue().size()), "part") + " left to cut");
  }
  RegionDecomposition result = episode_decomposition(episode, policy);
  result.policy_steps = static_cast<int>(actions.size());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace autoblock
