#include "core/env/episode_snapshot.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/error.h"
#include "core/common/format.h"

namespace autoblock {
namespace {

// The vertex of the running episode's current part at `position`, or -1.
int find_vertex(const Episode& episode, Point2 position, double tolerance) {
  int best = -1;
  double best_distance = tolerance;
  for (int v = 0; v < static_cast<int>(episode.current_vertices().size()); ++v) {
    const Point2 p = episode.vertex_position(v);
    const double distance = std::max(std::fabs(p.x - position.x), std::fabs(p.y - position.y));
    if (distance <= best_distance) {
      best = v;
      best_distance = distance;
    }
  }
  return best;
}

// Runs of consecutive cells along the line where `take(k)` holds, as segments.
template <class Take, class Point>
void collect_runs(int first, int last, Take take, Point point, std::vector<Segment>* out) {
  int start = -1;
  for (int k = first; k <= last + 1; ++k) {
    const bool on = k <= last && take(k);
    if (on && start < 0) start = k;
    if (!on && start >= 0) {
      out->push_back(Segment{point(start), point(k)});
      start = -1;
    }
  }
}

// The line clipped to the part: where it crosses the interior, else where it runs along the part.
std::vector<Segment> clip_line(const Part& part, const AxisLine& line) {
  const Grid& g = part.grid();
  std::vector<Segment> segments;
  for (bool interior : {true, false}) {
    if (line.direction == CutDirection::Vertical) {
      const int i = line.index;
      const double x = g.xs[static_cast<size_t>(i)];
      auto take = [&](int j) {
        const bool left = part.contains(i - 1, j), right = part.contains(i, j);
        return interior ? (left && right) : (left || right);
      };
      auto point = [&](int j) { return Point2{x, g.ys[static_cast<size_t>(j)]}; };
      collect_runs(part.j0(), part.j0() + part.height_cells() - 1, take, point, &segments);
    } else {
      const int j = line.index;
      const double y = g.ys[static_cast<size_t>(j)];
      auto take = [&](int i) {
        const bool below = part.contains(i, j - 1), above = part.contains(i, j);
        return interior ? (below && above) : (below || above);
      };
      auto point = [&](int i) { return Point2{g.xs[static_cast<size_t>(i)], y}; };
      collect_runs(part.i0(), part.i0() + part.width_cells() - 1, take, point, &segments);
    }
    if (!segments.empty()) break;
  }
  return segments;
}

std::string where(int index, const CutSpec& cut) {
  return "cut " + std::to_string(index + 1) + " (part " + std::to_string(cut.part_id) + ", vertex " +
         format_point(cut.vertex.x, cut.vertex.y) + ", " + direction_name(cut.direction) + ")";
}

}  // namespace

std::vector<CutSpec> cut_specs(const std::vector<CutRecord>& cuts) {
  std::vector<CutSpec> specs;
  specs.reserve(cuts.size());
  for (const CutRecord& cut : cuts) specs.push_back(CutSpec{cut.part_id, cut.position, cut.direction});
  return specs;
}

RectilinearPolygon part_polygon(const Part& part) {
  const Grid& g = part.grid();
  RectilinearPolygon polygon;
  const std::vector<CornerRing> loops = part_boundary(part);
  for (size_t l = 0; l < loops.size(); ++l) {
    Ring ring;
    ring.reserve(loops[l].size());
    for (const Corner& c : loops[l]) ring.push_back(Point2{g.xs[static_cast<size_t>(c.i)], g.ys[static_cast<size_t>(c.j)]});
    if (l == 0) {
      polygon.outer = std::move(ring);
    } else {
      polygon.holes.push_back(std::move(ring));
    }
  }
  return polygon;
}

namespace {

void check_step(int step, int steps) {
  if (step < 0 || step > steps) {
    throw InputError("step " + std::to_string(step) + " is out of range (the sequence has " + counted(steps, "cut") +
                     ")");
  }
}

// The action of cut `index` on the episode's current part, checked against the episode.
Action action_of(const Episode& episode, const std::vector<CutSpec>& cuts, int index) {
  const CutSpec& cut = cuts[static_cast<size_t>(index)];
  if (!episode.running()) throw InputError(where(index, cut) + ": the episode is already over");
  if (episode.current_part_id() != cut.part_id) {
    throw InputError(where(index, cut) + ": the part to cut is part " + std::to_string(episode.current_part_id()) +
                     "; the cut sequence does not belong to this face");
  }
  const int vertex = find_vertex(episode, cut.vertex, 1e-6 * episode.face().size);
  if (vertex < 0) {
    throw InputError(where(index, cut) + ": no corner of the part lies there; the cut sequence does not belong to "
                     "this face");
  }
  return Action{vertex, cut.direction};
}

// Plays a cut sequence, checking every cut against the episode.
class SequencePolicy : public Policy {
 public:
  SequencePolicy(const std::vector<CutSpec>& cuts, std::string name) : cuts_(cuts), name_(std::move(name)) {}
  std::string name() const override { return name_; }
  Action choose(const Episode& episode) override {
    if (next_ >= static_cast<int>(cuts_.size())) {
      throw InputError("the cut sequence ends after " + counted(static_cast<long long>(cuts_.size()), "cut") +
                       ", before the episode does; it does not belong to this face");
    }
    return action_of(episode, cuts_, next_++);
  }
  int used() const { return next_; }

 private:
  const std::vector<CutSpec>& cuts_;
  std::string name_;
  int next_ = 0;
};

}  // namespace

Episode replay_episode(const GridFace& face, const std::vector<CutSpec>& cuts, int step, EpisodeOptions options) {
  check_step(step, static_cast<int>(cuts.size()));
  Episode episode(face, options);
  for (int index = 0; index < step; ++index) episode.step(action_of(episode, cuts, index));
  return episode;
}

Decomposition replay_decomposition(const GridFace& face, const std::vector<CutSpec>& cuts, EpisodeOptions options,
                                   const std::string& policy) {
  SequencePolicy sequence(cuts, policy);
  Decomposition result = decompose_face(face, sequence, options);
  if (sequence.used() != static_cast<int>(cuts.size())) {
    throw InputError("the episode ends after " + std::to_string(sequence.used()) + " of the sequence's " +
                     counted(static_cast<long long>(cuts.size()), "cut") + "; the cut sequence does not belong to this face");
  }
  return result;
}

EpisodeSnapshot episode_snapshot(const GridFace& face, const std::vector<CutSpec>& cuts, int step,
                                 EpisodeOptions options) {
  const int steps = static_cast<int>(cuts.size());
  Episode episode = replay_episode(face, cuts, step, options);

  EpisodeSnapshot snapshot;
  snapshot.step = step;
  snapshot.steps = steps;
  snapshot.status = episode.status();
  snapshot.return_so_far = episode.total_return();
  snapshot.blocks = static_cast<int>(episode.blocks().size());
  for (const Piece& block : episode.blocks()) snapshot.pieces.push_back(SnapshotPiece{block.id, true, part_polygon(block.part)});
  for (const Piece& part : episode.queue()) snapshot.pieces.push_back(SnapshotPiece{part.id, false, part_polygon(part.part)});
  if (step < steps) {
    const Action action = action_of(episode, cuts, step);
    snapshot.has_next = true;
    snapshot.current_part_id = episode.current_part_id();
    for (int v = 0; v < static_cast<int>(episode.current_vertices().size()); ++v) {
      snapshot.vertices.push_back(episode.vertex_position(v));
    }
    snapshot.chosen_vertex = action.vertex;
    snapshot.direction = action.direction;
    snapshot.line = clip_line(episode.current_part(), episode.line_of(action));
    const std::vector<Part> pieces = episode.pieces_of(action);
    snapshot.n_parts = static_cast<int>(pieces.size());
    snapshot.reward = episode.reward_of(pieces);
  }
  return snapshot;
}

}  // namespace autoblock
