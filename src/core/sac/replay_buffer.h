// The replay buffer: what each SAC update needs about one cut.
//
// A cut of part P at vertex v in direction a earned reward r and left pieces; the pieces that are
// not rectangles (or P itself when nothing changed) are the cut's children, whose values the
// Bellman target adds up (the episode is a tree of parts, see sac_agent.h). States are shared:
// a child's state is the parent state of a later cut.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/sac/part_state.h"

namespace autoblock {

struct Transition {
  std::shared_ptr<const PartState> state;                  // the part that was cut
  int vertex = 0;                                          // index into state->observations
  int direction = 0;                                       // 0 horizontal, 1 vertical (grid faces)
  float reward = 0.0f;
  std::vector<std::shared_ptr<const PartState>> children;  // empty: every piece is a block
  float angle = 0.0f;                                      // general faces (continuous_sac_agent.h): the
                                                           // actor's squashed action u in [-1, 1]
  // General faces: per child, the reward of finishing it with the template (block.h), NaN where the
  // template does not apply (empty on grid faces: no child has one).
  std::vector<float> children_template;
};

class ReplayBuffer {
 public:
  explicit ReplayBuffer(size_t capacity);
  size_t size() const { return items_.size(); }
  size_t capacity() const { return capacity_; }
  // Adds a transition, replacing the oldest one when full.
  void add(Transition transition);
  // Inputs: count, rng. Output: count transitions drawn uniformly with replacement (size() > 0).
  std::vector<const Transition*> sample(size_t count, std::mt19937_64& rng) const;
  const Transition& at(size_t k) const { return items_[k]; }

  // Binary form for checkpoints (states written once each; version 2 adds the angle and the
  // children's template rewards, version 1 still reads).
  std::string serialize() const;
  // Throws InputError when bytes are malformed.
  static ReplayBuffer deserialize(const std::string& bytes);

 private:
  size_t capacity_;
  size_t next_ = 0;  // slot the next add overwrites once full
  std::vector<Transition> items_;
};

}  // namespace autoblock
