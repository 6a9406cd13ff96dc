#include "core/sac/replay_buffer.h"

#include <cstring>
#include <map>
#include <stdexcept>

#include "core/common/error.h"

namespace autoblock {
namespace {

constexpr char kMagic[4] = {'A', 'B', 'R', 'B'};
constexpr std::uint32_t kVersion = 2;

class Writer {
 public:
  template <typename T>
  void put(const T& value) {
    const char* p = reinterpret_cast<const char*>(&value);
    bytes.append(p, sizeof(T));
  }
  template <typename T>
  void put_vector(const std::vector<T>& values) {
    put<std::uint64_t>(values.size());
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  std::string bytes;
};

class Reader {
 public:
  explicit Reader(const std::string& b) : bytes(b) {}
  template <typename T>
  T get() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
    offset += sizeof(T);
    return value;
  }
  template <typename T>
  std::vector<T> get_vector() {
    const auto n = get<std::uint64_t>();
    if (n > bytes.size()) throw InputError("corrupt replay buffer (bad length)");
    need(n * sizeof(T));
    std::vector<T> values(n);
    std::memcpy(values.data(), bytes.data() + offset, n * sizeof(T));
    offset += n * sizeof(T);
    return values;
  }
  void need(size_t n) const {
    if (offset + n > bytes.size()) throw InputError("corrupt replay buffer (truncated)");
  }
  const std::string& bytes;
  size_t offset = 0;
};

}  // namespace

ReplayBuffer::ReplayBuffer(size_t capacity) : capacity_(capacity) {
  if (capacity == 0) throw InputError("the replay buffer needs a capacity of at least 1");
}

void ReplayBuffer::add(Transition transition) {
  if (items_.size() < capacity_) {
    items_.push_back(std::move(transition));
  } else {
    items_[next_] = std::move(transition);
    next_ = (next_ + 1) % capacity_;
  }
}

std::vector<const Transition*> ReplayBuffer::sample(size_t count, std::mt19937_64& rng) const {
  if (items_.empty()) throw std::logic_error("ReplayBuffer::sample: empty buffer");
  std::uniform_int_distribution<size_t> pick(0, items_.size() - 1);
  std::vector<const Transition*> batch;
  batch.reserve(count);
  for (size_t k = 0; k < count; ++k) batch.push_back(&items_[pick(rng)]);
  return batch;
}

std::string ReplayBuffer::serialize() const {
  std::map<const PartState*, std::uint32_t> index;
  std::vector<const PartState*> states;
  auto id_of = [&](const std::shared_ptr<const PartState>& s) {
    const auto found = index.find(s.get());
    if (found != index.end()) return found->second;
    const auto id = static_cast<std::uint32_t>(states.size());
    index.emplace(s.get(), id);
    states.push_back(s.get());
    return id;
  };
  for (const Transition& t : items_) {
    id_of(t.state);
    for (const auto& c : t.children) id_of(c);
  }
  Writer w;
  w.bytes.append(kMagic, 4);
  w.put(kVersion);
  w.put<std::uint64_t>(capacity_);
  w.put<std::uint64_t>(next_);
  w.put<std::uint64_t>(states.size());
  for (const PartState* s : states) {
    w.put_vector(s->graph.positions);
    w.put_vector(s->graph.features);
    w.put_vector(s->graph.edges);
    w.put_vector(s->graph.pseudo);
    w.put_vector(s->graph.vertex_nodes);
    w.put_vector(s->observations);
  }
  w.put<std::uint64_t>(items_.size());
  for (const Transition& t : items_) {
    w.put(index.at(t.state.get()));
    w.put<std::int32_t>(t.vertex);
    w.put<std::int32_t>(t.direction);
    w.put(t.angle);
    w.put(t.reward);
    w.put<std::uint32_t>(static_cast<std::uint32_t>(t.children.size()));
    for (const auto& c : t.children) w.put(index.at(c.get()));
    w.put_vector(t.children_template);
  }
  return w.bytes;
}

ReplayBuffer ReplayBuffer::deserialize(const std::string& bytes) {
  Reader r(bytes);
  r.need(4);
  if (std::memcmp(bytes.data(), kMagic, 4) != 0) throw InputError("corrupt replay buffer (bad magic)");
  r.offset = 4;
  const auto version = r.get<std::uint32_t>();
  if (version != 1 && version != kVersion) throw InputError("replay buffer of an unsupported version");
  ReplayBuffer buffer(static_cast<size_t>(r.get<std::uint64_t>()));
  buffer.next_ = static_cast<size_t>(r.get<std::uint64_t>());
  const auto state_count = r.get<std::uint64_t>();
  if (state_count > bytes.size()) throw InputError("corrupt replay buffer (bad state count)");
  std::vector<std::shared_ptr<const PartState>> states;
  for (std::uint64_t k = 0; k < state_count; ++k) {
    auto s = std::make_shared<PartState>();
    s->graph.positions = r.get_vector<Point2>();
    s->graph.features = r.get_vector<std::array<float, 3>>();
    s->graph.edges = r.get_vector<std::array<int, 2>>();
    s->graph.pseudo = r.get_vector<std::array<float, 2>>();
    s->graph.vertex_nodes = r.get_vector<int>();
    s->observations = r.get_vector<Observation>();
    const int nodes = static_cast<int>(s->graph.positions.size());
    bool ok = s->graph.features.size() == s->graph.positions.size() &&
              s->graph.edges.size() == s->graph.pseudo.size() &&
              s->observations.size() == s->graph.vertex_nodes.size();
    for (const auto& e : s->graph.edges) ok = ok && e[0] >= 0 && e[0] < nodes && e[1] >= 0 && e[1] < nodes;
    for (int v : s->graph.vertex_nodes) ok = ok && v >= 0 && v < nodes;
    if (!ok) throw InputError("corrupt replay buffer (inconsistent graph)");
    states.push_back(std::move(s));
  }
  const auto item_count = r.get<std::uint64_t>();
  if (item_count > buffer.capacity_) throw InputError("corrupt replay buffer (too many transitions)");
  auto state_at = [&](std::uint32_t id) {
    if (id >= states.size()) throw InputError("corrupt replay buffer (bad state index)");
    return states[id];
  };
  for (std::uint64_t k = 0; k < item_count; ++k) {
    Transition t;
    t.state = state_at(r.get<std::uint32_t>());
    t.vertex = r.get<std::int32_t>();
    t.direction = r.get<std::int32_t>();
    if (version >= 2) t.angle = r.get<float>();
    t.reward = r.get<float>();
    if (t.vertex < 0 || t.vertex >= static_cast<int>(t.state->observations.size()) || t.direction < 0 ||
        t.direction > 1 || !(t.angle >= -1.0f && t.angle <= 1.0f)) {
      throw InputError("corrupt replay buffer (bad action)");
    }
    const auto children = r.get<std::uint32_t>();
    for (std::uint32_t c = 0; c < children; ++c) t.children.push_back(state_at(r.get<std::uint32_t>()));
    if (version >= 2) {
      t.children_template = r.get_vector<float>();
      if (!t.children_template.empty() && t.children_template.size() != t.children.size()) {
        throw InputError("corrupt replay buffer (bad template rewards)");
      }
    }
    buffer.items_.push_back(std::move(t));
  }
  if (buffer.items_.size() == buffer.capacity_ ? buffer.next_ >= buffer.capacity_ : buffer.next_ != 0) {
    throw InputError("corrupt replay buffer (bad position)");
  }
  return buffer;
}

}  // namespace autoblock
