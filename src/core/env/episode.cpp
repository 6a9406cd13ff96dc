#include "core/env/episode.h"

#include <stdexcept>


namespace autoblock {

std::string status_name(EpisodeStatus status) {
  switch (status) {
    case EpisodeStatus::Running: return "running";
    case EpisodeStatus::Complete: return "complete";
    case EpisodeStatus::Truncated: return "truncated";
  }
  return "unknown";
}

Episode::Episode(const GridFace& face, EpisodeOptions options) : face_(face), reward_(options.reward) {
  if (options.max_steps > 0) {
    max_steps_ = options.max_steps;
  } else {
    size_t corners = 0;
    for (const CornerRing& loop : part_boundary(face.whole)) corners += loop.size();
    max_steps_ = 10 * static_cast<int>(corners) + 10;
  }
  push(face.whole, nullptr);
  refresh_current();
}

void Episode::push(Part part, std::vector<int>* ids) {
  const int id = next_id_++;
  if (ids) ids->push_back(id);
  if (part.is_rectangle()) {
    blocks_.push_back(Piece{id, std::move(part)});
  } else {
    queue_.push_back(Piece{id, std::move(part)});
  }
}

void Episode::refresh_current() {
  loops_.clear();
  vertices_.clear();
  if (queue_.empty()) {
    status_ = EpisodeStatus::Complete;
    return;
  }
  if (steps() >= max_steps_) {
    status_ = EpisodeStatus::Truncated;
    return;
  }
  loops_ = part_boundary(queue_.front().part);
  for (int l = 0; l < static_cast<int>(loops_.size()); ++l) {
    for (int k = 0; k < static_cast<int>(loops_[static_cast<size_t>(l)].size()); ++k) {
      vertices_.push_back(VertexRef{loops_[static_cast<size_t>(l)][static_cast<size_t>(k)], l, k});
    }
  }
}

Observation Episode::observe(int vertex) const {
  const VertexRef& v = vertices_.at(static_cast<size_t>(vertex));
  return observe_vertex(current_part(), loops_, v.loop, v.index);
}

Point2 Episode::vertex_position(int vertex) const {
  const Corner& c = vertices_.at(static_cast<size_t>(vertex)).corner;
  return Point2{face_.grid->xs[static_cast<size_t>(c.i)], face_.grid->ys[static_cast<size_t>(c.j)]};
}

int Episode::vertex_at(const Corner& corner) const {
  for (int v = 0; v < static_cast<int>(vertices_.size()); ++v) {
    const Corner& c = vertices_[static_cast<size_t>(v)].corner;
    if (c.i == corner.i && c.j == corner.j) return v;
  }
  return -1;
}

AxisLine Episode::line_of(const Action& action) const {
  const Corner& c = vertices_.at(static_cast<size_t>(action.vertex)).corner;
  return AxisLine{action.direction, action.direction == CutDirection::Vertical ? c.i : c.j};
}

std::vector<Part> Episode::pieces_of(const Action& action) const {
  return cut_part(current_part(), line_of(action));
}

double Episode::reward_of(const std::vector<Part>& pieces) const { return cut_reward(reward_, pieces, face_.size); }

const CutRecord& Episode::step(const Action& action) {
  if (!running()) throw std::logic_error("Episode::step: the episode is over");
  if (action.vertex < 0 || action.vertex >= static_cast<int>(vertices_.size())) {
    throw std::logic_error("Episode::step: no such vertex");
  }
  CutRecord record;
  record.part_id = current_part_id();
  record.vertex = vertices_[static_cast<size_t>(action.vertex)].corner;
  record.position = vertex_position(action.vertex);
  record.direction = action.direction;
  std::vector<Part> pieces = pieces_of(action);
  record.n_parts = static_cast<int>(pieces.size());
  record.reward = reward_of(pieces);
  if (pieces.size() == 1) {
    // Nothing changed: the same part goes to the back of the queue.
    record.children.push_back(record.part_id);
    queue_.push_back(queue_.front());
    queue_.pop_front();
  } else {
    queue_.pop_front();
    for (Part& piece : pieces) push(std::move(piece), &record.children);
  }
  return_ += record.reward;
  cuts_.push_back(std::move(record));
  refresh_current();
  return cuts_.back();
}

}  // namespace autoblock
