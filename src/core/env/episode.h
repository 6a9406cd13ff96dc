// One decomposition episode, as in the paper: cut the part at the front of a FIFO queue with a full
// axis-parallel line through one of its model vertices; set rectangles aside; queue the other
// pieces; stop when every piece is a rectangle (complete) or at the step cap (truncated).
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "core/env/observation.h"
#include "core/env/reward.h"
#include "core/geometry/axis_cut.h"
#include "core/geometry/grid_face.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {

// A cut at the current part's vertex number `vertex` (see Episode::current_vertices).
struct Action {
  int vertex = 0;
  CutDirection direction = CutDirection::Horizontal;
};

enum class EpisodeStatus { Running, Complete, Truncated };
std::string status_name(EpisodeStatus status);

struct EpisodeOptions {
  int max_steps = 0;                        // 0: automatic, 10 x (corners of the face) + 10
  RewardPreset reward = RewardPreset::Paper;
};

// A model vertex of the current part: corner `index` of boundary loop `loop`.
struct VertexRef {
  Corner corner;
  int loop = 0;
  int index = 0;
};

// A piece of the face with its id: 0 is the face itself, cuts number their pieces 1, 2, ...
struct Piece {
  int id = 0;
  Part part;
};

struct CutRecord {
  int part_id = 0;           // the part that was cut
  Corner vertex;             // the chosen vertex (grid indices) ...
  Point2 position;           // ... and its coordinates
  CutDirection direction = CutDirection::Horizontal;
  int n_parts = 1;           // N: pieces the cut left (1: nothing changed)
  double reward = 0.0;       // the episode's reward preset (Eq. (1) by default)
  std::vector<int> children; // ids of the pieces ({part_id} when N = 1)
};

class Episode {
 public:
  explicit Episode(const GridFace& face, EpisodeOptions options = {});

  const GridFace& face() const { return face_; }
  EpisodeStatus status() const { return status_; }
  bool running() const { return status_ == EpisodeStatus::Running; }
  int max_steps() const { return max_steps_; }
  int steps() const { return static_cast<int>(cuts_.size()); }

  // The part to cut next (front of the queue) and its model vertices. Only while running.
  const Part& current_part() const { return queue_.front().part; }
  int current_part_id() const { return queue_.front().id; }
  const std::vector<CornerRing>& current_loops() const { return loops_; }
  const std::vector<VertexRef>& current_vertices() const { return vertices_; }
  Observation observe(int vertex) const;
  Point2 vertex_position(int vertex) const;
  // The number of the current part's vertex at that grid corner, or -1 when it is not one.
  int vertex_at(const Corner& corner) const;

  // The line of an action on the current part, the pieces it would leave and their reward, without
  // changing anything.
  AxisLine line_of(const Action& action) const;
  std::vector<Part> pieces_of(const Action& action) const;
  double reward_of(const std::vector<Part>& pieces) const;

  // Cuts the current part. Throws std::logic_error when not running or the vertex is out of range.
  const CutRecord& step(const Action& action);

  const std::vector<Piece>& blocks() const { return blocks_; }         // rectangles, in order set aside
  const std::deque<Piece>& queue() const { return queue_; }            // parts still to cut
  const std::vector<CutRecord>& cuts() const { return cuts_; }
  double total_return() const { return return_; }                    // plain sum of the cuts' rewards
  RewardPreset reward_preset() const { return reward_; }

 private:
  void push(Part part, std::vector<int>* ids);
  void refresh_current();

  GridFace face_;
  int max_steps_ = 0;
  RewardPreset reward_ = RewardPreset::Paper;
  EpisodeStatus status_ = EpisodeStatus::Running;
  std::deque<Piece> queue_;
  std::vector<Piece> blocks_;
  std::vector<CutRecord> cuts_;
  std::vector<CornerRing> loops_;
  std::vector<VertexRef> vertices_;
  double return_ = 0.0;
  int next_id_ = 0;
};

}  // namespace autoblock
