#include "support/catch_torch.h"

#include "core/common/error.h"
#include "core/sac/replay_buffer.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {
std::shared_ptr<const PartState> l_state() {
  return make_part_state(test::grid_face_of(test::l_shape()).whole, GraphOptions{});
}
Transition transition(const std::shared_ptr<const PartState>& s, float reward, int children) {
  Transition t;
  t.state = s;
  t.vertex = 3;
  t.direction = 1;
  t.reward = reward;
  for (int c = 0; c < children; ++c) t.children.push_back(s);
  return t;
}
}  // namespace

TEST_CASE("the replay buffer keeps the newest transitions up to its capacity", "[sac]") {
  ReplayBuffer buffer(3);
  const auto s = l_state();
  for (int k = 0; k < 5; ++k) buffer.add(transition(s, static_cast<float>(k), 0));
  REQUIRE(buffer.size() == 3);
  std::vector<float> rewards;
  for (size_t k = 0; k < buffer.size(); ++k) rewards.push_back(buffer.at(k).reward);
  std::sort(rewards.begin(), rewards.end());
  CHECK(rewards == std::vector<float>{2, 3, 4});
  std::mt19937_64 rng(1);
  const auto batch = buffer.sample(8, rng);
  CHECK(batch.size() == 8);
  for (const Transition* t : batch) CHECK(t->reward >= 2);
}

TEST_CASE("the replay buffer survives a round trip through bytes, sharing states", "[sac]") {
  ReplayBuffer buffer(4);
  const auto s = l_state();
  buffer.add(transition(s, 1.5f, 2));
  buffer.add(transition(s, -3.0f, 0));
  const ReplayBuffer copy = ReplayBuffer::deserialize(buffer.serialize());
  REQUIRE(copy.size() == 2);
  CHECK(copy.capacity() == 4);
  CHECK(copy.at(0).reward == 1.5f);
  CHECK(copy.at(0).children.size() == 2);
  CHECK(copy.at(0).children[0] == copy.at(0).state);  // shared, not duplicated
  CHECK((copy.at(0).state->graph.edges == s->graph.edges));
  CHECK((copy.at(0).state->observations == s->observations));
  CHECK(copy.at(1).vertex == 3);
  CHECK(copy.at(1).direction == 1);
}

TEST_CASE("corrupt replay buffer bytes are an InputError, never a crash", "[sac][errors]") {
  ReplayBuffer buffer(4);
  buffer.add(transition(l_state(), 1.0f, 1));
  const std::string bytes = buffer.serialize();
  CHECK_THROWS_AS(ReplayBuffer::deserialize(""), InputError);
  CHECK_THROWS_AS(ReplayBuffer::deserialize("XXXX" + bytes.substr(4)), InputError);
  for (size_t cut : {size_t{5}, bytes.size() / 3, bytes.size() - 1}) {
    CHECK_THROWS_AS(ReplayBuffer::deserialize(bytes.substr(0, cut)), InputError);
  }
}
