#include "core/sac/lookahead_agent.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <stdexcept>

#include "core/common/error.h"
#include "core/geometry/part_boundary.h"
#include "core/geometry/part_symmetry.h"
#include "core/nn/module_blend.h"
#include "core/region/region_candidates.h"
#include "core/region/region_symmetry.h"
#include "core/sac/continuous_sac_agent.h"
#include "core/sac/deploy_profile.h"
#include "core/sac/region_lookahead_policy.h"
#include "core/sac/softmax_draw.h"
#include "core/sac/state_batch.h"

namespace autoblock {
namespace {

// Entropy of softmax(q / alpha).
double softmax_entropy(const std::vector<double>& q, double alpha) {
  const double top = *std::max_element(q.begin(), q.end());
  double z = 0.0;
  for (double v : q) z += std::exp((v - top) / alpha);
  double h = 0.0;
  for (double v : q) {
    const double p = std::exp((v - top) / alpha) / z;
    if (p > 0) h -= p * std::log(p);
  }
  return h;
}

double soft_maximum(const std::vector<double>& q, double alpha) {
  const double top = *std::max_element(q.begin(), q.end());
  double z = 0.0;
  for (double v : q) z += std::exp((v - top) / alpha);
  return top + alpha * std::log(z);
}

}  // namespace

LookaheadPolicy::LookaheadPolicy(std::shared_ptr<LookaheadAgent> agent, std::string name)
    : agent_(std::move(agent)), name_(std::move(name)), reuse_values_(agent_->deploy_reuse()) {}

Action LookaheadPolicy::choose(const Episode& episode) {
  const auto state = state_of(episode.current_part(), episode.face().size);
  const std::vector<double> q = values(*state, episode.face().size);
  const size_t best = static_cast<size_t>(std::max_element(q.begin(), q.end()) - q.begin());
  const LineCandidate& line = state->lines[best];
  return Action{line.vertex, line.line.direction};
}

std::vector<double> LookaheadPolicy::values(const PartState& state, double face_size) {
  static constexpr int kViewOrder[8] = {0, 4, 2, 6, 1, 5, 3, 7};  // identity, half turn, quarter turns, mirrors
  const int views = std::clamp(agent_->config().deploy_views, 1, 8);
  if (!reuse_values_) values_.clear();
  // The views of every piece not valued yet, in one batch.
  const bool bounded = agent_->config().graph.method == GraphMethod::Bounded;
  std::vector<const Part*> fresh;
  std::vector<std::shared_ptr<const PartState>> keep;
  std::vector<const PartState*> batch;
  long reused = 0;
  const std::vector<size_t> shortlisted = shortlist(state, face_size);
  for (const size_t l : shortlisted) {
    for (const Part& piece : state.lines[l].to_cut) {
      const auto [slot, inserted] = values_.try_emplace(piece, 0.0);
      if (!inserted) {
        reused += std::find_if(fresh.begin(), fresh.end(), [&](const Part* p) { return *p == piece; }) == fresh.end();
        continue;
      }
      fresh.push_back(&slot->first);
      const std::shared_ptr<const PartState> base = state_of(piece, face_size);
      for (int v = 0; v < views; ++v) {
        const int symmetry = kViewOrder[v];
        if (symmetry == 0) {
          keep.push_back(base);
        } else if (bounded) {
          keep.push_back(symmetric_view(*base, symmetry));  // no second triangulation
        } else {
          // Refined graphs (policies trained before issue 8): the transformed part's own
          // triangulation, as those policies were validated with.
          auto& view = refined_views_[symmetry][piece];
          if (!view) view = make_part_state(transform_part(piece, symmetry), agent_->state_options(face_size));
          keep.push_back(view);
        }
        batch.push_back(keep.back().get());
      }
    }
  }
  deploy_profile().values_reused += reused;
  if (!batch.empty()) {
    const std::vector<double> w = agent_->deployed_values(batch);
    for (size_t p = 0; p < fresh.size(); ++p) {
      double mean = 0.0;
      for (int v = 0; v < views; ++v) mean += w[p * static_cast<size_t>(views) + static_cast<size_t>(v)];
      values_[*fresh[p]] = mean / views;
    }
  }
  std::vector<double> q(state.lines.size(), -std::numeric_limits<double>::infinity());
  for (const size_t l : shortlisted) {
    const LineCandidate& line = state.lines[l];
    double value = line.reward;
    for (const Part& piece : line.to_cut) value += agent_->config().gamma * values_.at(piece);
    q[l] = value;
  }
  return q;
}

std::vector<size_t> LookaheadPolicy::shortlist(const PartState& state, double face_size) {
  std::vector<size_t> order(state.lines.size());
  std::iota(order.begin(), order.end(), size_t{0});
  const int k = agent_->config().deploy_top_k;
  if (k <= 0 || static_cast<size_t>(k) >= order.size()) return order;
  std::vector<double> score;
  score.reserve(state.lines.size());
  for (const LineCandidate& line : state.lines) {
    double s = line.reward;
    for (const Part& piece : line.to_cut) s += agent_->config().gamma * piece_estimate(piece, face_size);
    score.push_back(s);
  }
  std::partial_sort(order.begin(), order.begin() + k, order.end(),
                    [&](size_t a, size_t b) { return score[a] != score[b] ? score[a] > score[b] : a < b; });
  order.resize(static_cast<size_t>(k));
  std::sort(order.begin(), order.end());
  return order;
}

double LookaheadPolicy::piece_estimate(const Part& piece, double face_size) {
  const auto cached = estimates_.find(piece);
  if (cached != estimates_.end()) return cached->second;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CornerRing> loops = part_boundary(piece);
  const PartLookahead ahead = look_ahead(piece, loops, face_size, agent_->config().reward);
  double best = ahead.lines.empty() ? 0.0 : -std::numeric_limits<double>::infinity();
  for (const LineCandidate& line : ahead.lines) best = std::max(best, line.reward);
  int reflex = 0;
  for (const CornerRing& loop : loops) {
    for (const Corner& corner : loop) reflex += corner.reflex;
  }
  const double estimate = best * std::max(1.0, 0.5 * (reflex + 1));
  deploy_profile().lookahead_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  estimates_.emplace(piece, estimate);
  return estimate;
}

std::shared_ptr<const PartState> LookaheadPolicy::state_of(const Part& part, double face_size) {
  auto& slot = states_[part];
  if (!slot) slot = make_part_state(part, agent_->state_options(face_size));
  return slot;
}

LookaheadAgent::LookaheadAgent(const SacConfig& config)
    : config_(config), scale_(lookahead_reward_scale(config.reward)) {
  ValueNetworkConfig network = ValueNetworkConfig::by_name(config.value_network);
  network.inputs = kLookaheadFeatures;
  value_ = ValueNetwork(network);
  target_ = ValueNetwork(network);
  blend_module(*target_, *value_, 1.0);
  target_->eval();
  if (averaging()) {
    average_ = ValueNetwork(network);
    blend_module(*average_, *value_, 1.0);
    average_->eval();
  }
  log_alpha_ = torch::full({}, std::log(config.initial_direction_temperature * scale_), torch::requires_grad());
  value_optimizer_ = std::make_unique<torch::optim::Adam>(value_->parameters(), torch::optim::AdamOptions(config.lr_value));
  temperature_optimizer_ = std::make_unique<torch::optim::Adam>(std::vector<torch::Tensor>{log_alpha_},
                                                                torch::optim::AdamOptions(config.lr_temperature));
  // Made last: a configuration without proposals draws the same initial weights as before them.
  if (config.actor_candidates > 0) proposer_ = std::make_unique<CutProposer>(config);
}

void LookaheadAgent::set_training_progress(double fraction) {
  // Half-cosine decay of the value network's learning rate from lr_value to
  // lr_final_fraction * lr_value: late updates refine instead of jumping between nearby solutions.
  const double p = std::clamp(fraction, 0.0, 1.0);
  const double f = config_.lr_final_fraction;
  const double lr = config_.lr_value * (f + (1.0 - f) * 0.5 * (1.0 + std::cos(M_PI * p)));
  for (auto& group : value_optimizer_->param_groups()) {
    static_cast<torch::optim::AdamOptions&>(group.options()).lr(lr);
  }
}

void LookaheadAgent::prepare_checkpoint() {
  target_values_.clear();
  region_target_values_.clear();
}

double LookaheadAgent::learning_rate() const {
  return static_cast<const torch::optim::AdamOptions&>(value_optimizer_->param_groups().front().options()).lr();
}

PartStateOptions LookaheadAgent::state_options(double face_size) const {
  PartStateOptions options(config_.graph);
  options.lookahead = true;
  options.reward = config_.reward;
  options.face_size = face_size;
  return options;
}

RegionStateOptions LookaheadAgent::region_state_options(double face_size, const BlockRules& rules) const {
  RegionStateOptions options;
  options.graph = config_.graph;
  options.lookahead = true;
  options.episode.reward = config_.reward;
  options.episode.rules = rules;
  options.episode.face_rules = false;
  options.face_size = face_size;
  options.taper = config_.region_taper && config_.reward == RewardPreset::Mesh;
  return options;
}

bool LookaheadAgent::RegionKey::operator==(const RegionKey& other) const {
  return face_size == other.face_size && rules.min_corner_degrees == other.rules.min_corner_degrees &&
         rules.max_corner_degrees == other.rules.max_corner_degrees &&
         rules.flat_tolerance_degrees == other.rules.flat_tolerance_degrees && region == other.region;
}

size_t LookaheadAgent::RegionKeyHash::operator()(const RegionKey& key) const {
  return key.region.hash() ^ (std::hash<double>()(key.face_size) * 0x9e3779b97f4a7c15ULL) ^
         std::hash<double>()(key.rules.min_corner_degrees + 1e3 * key.rules.max_corner_degrees);
}

std::shared_ptr<const RegionPartState> LookaheadAgent::cached_region_state(const Region& region, double face_size,
                                                                           const BlockRules& rules) {
  if (region_states_.size() > 50000) region_states_.clear();  // a memory bound; states are rebuilt on demand
  auto& slot = region_states_[RegionKey{region, face_size, rules}];
  if (!slot) slot = make_region_state(region, region_state_options(face_size, rules));
  return slot;
}

std::vector<double> LookaheadAgent::region_action_values(const RegionPartState& state, const std::vector<size_t>& which,
                                                         double face_size, const BlockRules& rules) {
  std::vector<const RegionCandidate*> candidates;
  for (const size_t k : which) candidates.push_back(&state.candidates[k]);
  return candidate_values(candidates, face_size, rules);
}

std::vector<double> LookaheadAgent::candidate_values(const std::vector<const RegionCandidate*>& candidates,
                                                     double face_size, const BlockRules& rules) {
  std::vector<const PartState*> children;
  std::vector<std::shared_ptr<const RegionPartState>> keep;
  for (const RegionCandidate* candidate : candidates) {
    for (const Region& piece : candidate->to_cut) {
      keep.push_back(cached_region_state(piece, face_size, rules));
      children.push_back(keep.back().get());
    }
  }
  const std::vector<double> w = children.empty() ? std::vector<double>{} : state_values(children);
  std::vector<double> q;
  size_t c = 0;
  for (const RegionCandidate* candidate : candidates) {
    double value = candidate->reward;
    for (size_t p = 0; p < candidate->to_cut.size(); ++p) value += config_.gamma * w[c++];
    q.push_back(value);
  }
  return q;
}

std::vector<LookaheadAgent::ProposedCut> LookaheadAgent::propose_cuts(const Region& part, const RegionPartState& state,
                                                                      double face_size, const BlockRules& rules,
                                                                      std::mt19937_64* rng) {
  std::vector<ProposedCut> proposals;
  if (!proposer_) return proposals;
  // The next vertex along its loop of every vertex (loops flattened, Region::loops order).
  std::vector<Point2> vertex, next;
  for (const Ring& loop : part.loops()) {
    for (size_t i = 0; i < loop.size(); ++i) {
      vertex.push_back(loop[i]);
      next.push_back(loop[(i + 1) % loop.size()]);
    }
  }
  for (const size_t base : best_at_vertices(state.candidates, static_cast<size_t>(config_.actor_candidates))) {
    ProposedCut proposal;
    proposal.base = base;
    proposal.vertex = state.candidates[base].vertex;
    const size_t i = static_cast<size_t>(proposal.vertex);
    proposal.input = proposal_input(state.observations.at(i), Point2{next[i].x - vertex[i].x, next[i].y - vertex[i].y},
                                    state.candidates[proposal.base].action.cut.direction);
    proposals.push_back(std::move(proposal));
  }
  std::vector<const ProposalInput*> inputs;
  for (const ProposedCut& proposal : proposals) inputs.push_back(&proposal.input);
  const std::vector<CutProposer::Draw> draws = proposer_->draw(inputs, rng);
  const RegionStateOptions options = region_state_options(face_size, rules);
  for (size_t k = 0; k < proposals.size(); ++k) {
    ProposedCut& proposal = proposals[k];
    proposal.draw = draws[k];
    RegionAction action;
    action.cut = turned_cut(state.candidates[proposal.base].action.cut, draws[k].u);
    proposal.candidate = region_candidate(part, action, face_size, options.episode, options.taper);
    if (proposal.candidate) proposal.candidate->vertex = proposal.vertex;
  }
  return proposals;
}

double LookaheadAgent::temperature() const { return std::exp(log_alpha_.item<double>()); }

torch::Tensor LookaheadAgent::forward_values(ValueNetwork& network, const std::vector<const PartState*>& states) {
  const GraphBatch batch = batch_states(states);
  const torch::Tensor vertex_out = network->forward(batch.x, batch.edge_index, batch.pseudo).index_select(0, batch.vertex_nodes);
  std::vector<int64_t> owner;
  owner.reserve(static_cast<size_t>(vertex_out.size(0)));
  for (size_t g = 0; g + 1 < batch.vertex_offsets.size(); ++g) {
    for (int64_t k = batch.vertex_offsets[g]; k < batch.vertex_offsets[g + 1]; ++k) owner.push_back(static_cast<int64_t>(g));
  }
  return torch::zeros({static_cast<int64_t>(states.size())}).index_add(0, torch::tensor(owner, torch::kInt64), vertex_out) *
         scale_;
}

std::vector<double> LookaheadAgent::values_of(ValueNetwork& network, const std::vector<const PartState*>& states) {
  torch::NoGradGuard no_grad;
  network->eval();
  const torch::Tensor w = forward_values(network, states).contiguous();
  return std::vector<double>(w.data_ptr<float>(), w.data_ptr<float>() + w.numel());
}

std::vector<double> LookaheadAgent::state_values(const std::vector<const PartState*>& states) {
  return values_of(value_, states);
}

std::vector<double> LookaheadAgent::deployed_values(const std::vector<const PartState*>& states) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> values = values_of(averaging() ? average_ : value_, states);
  DeployProfile& profile = deploy_profile();
  profile.forward_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++profile.forwards;
  profile.graphs_evaluated += static_cast<long>(states.size());
  return values;
}

void LookaheadAgent::update_average() {
  // average <- d average + (1 - d) trained, for the weights and batch norm's running statistics,
  // with d = min(decay, (1 + updates) / (10 + updates)) so that early on the average does not hold on
  // to the untrained initial weights.
  const double u = static_cast<double>(updates_);
  const double d = std::min(config_.weight_average_decay, (1.0 + u) / (10.0 + u));
  blend_module(*average_, *value_, 1.0 - d, BufferBlend::Average);
}

std::vector<double> LookaheadAgent::cut_values(const PartState& state, double face_size) {
  std::vector<const PartState*> children;
  std::vector<std::shared_ptr<const PartState>> keep;
  for (const LineCandidate& line : state.lines) {
    for (const Part& piece : line.to_cut) {
      keep.push_back(cached_state(piece, face_size));
      children.push_back(keep.back().get());
    }
  }
  const std::vector<double> w = children.empty() ? std::vector<double>{} : state_values(children);
  std::vector<double> q;
  size_t k = 0;
  for (const LineCandidate& line : state.lines) {
    double value = line.reward;
    for (size_t c = 0; c < line.to_cut.size(); ++c) value += config_.gamma * w[k++];
    q.push_back(value);
  }
  return q;
}

std::shared_ptr<const PartState> LookaheadAgent::cached_state(const Part& part, double face_size) {
  if (states_.size() > 200000) states_.clear();  // a memory bound; states are rebuilt on demand
  auto& slot = states_[GridKey{part, face_size}];
  if (!slot) slot = make_part_state(part, state_options(face_size));
  return slot;
}

void LookaheadAgent::remember(const Part& part, double face_size, int symmetry) {
  Memory entry;
  entry.part = part;
  entry.face_size = face_size;
  entry.symmetry = symmetry;
  push_memory(std::move(entry));
}

void LookaheadAgent::push_memory(Memory entry) {
  if (memory_.size() < static_cast<size_t>(config_.buffer_capacity)) {
    memory_.push_back(std::move(entry));
  } else {
    memory_[next_] = std::move(entry);
    next_ = (next_ + 1) % memory_.size();
  }
}

void LookaheadAgent::remember_region(const Region& part, double face_size, const BlockRules& rules, double angle,
                                     bool mirror) {
  Memory entry;
  entry.region = part;
  entry.face_size = face_size;
  entry.rules = rules;
  entry.angle = angle;
  entry.mirror = mirror;
  push_memory(std::move(entry));
}

EpisodeRecord LookaheadAgent::train_region_episode(const Region& face, std::mt19937_64& rng, int max_steps) {
  std::unique_lock<std::mutex> lock = lock_general_engine();
  RegionEpisodeOptions options;
  options.reward = config_.reward;
  options.max_steps = max_steps;
  RegionEpisode episode(face, options);
  const double face_size = episode.face_size();
  const BlockRules rules = episode.options().rules;
  std::map<std::string, double> metric_sums;
  int updates = 0;
  std::vector<CutProposer::Sample> proposal_samples;  // this episode's (cut_proposer.h)
  while (episode.running()) {
    const Region part = episode.current_part();
    const auto state = cached_region_state(part, face_size, rules);
    if (state->candidates.empty()) {  // nothing makes progress (not met on valid faces): finish as every policy does
      episode.step(progress_action(part, rules));
      continue;
    }
    const std::vector<size_t> actions = best_candidates(state->candidates, static_cast<size_t>(config_.train_top_k));
    RegionAction chosen;
    if (steps_ < config_.warmup_steps) {
      chosen = state->candidates[actions[std::uniform_int_distribution<size_t>(0, actions.size() - 1)(rng)]].action;
    } else {
      std::vector<const RegionCandidate*> listed;
      for (const size_t a : actions) listed.push_back(&state->candidates[a]);
      const std::vector<ProposedCut> proposals = propose_cuts(part, *state, face_size, rules, &rng);
      std::vector<const RegionCandidate*> all = listed;
      for (const ProposedCut& proposal : proposals) {
        if (proposal.candidate) all.push_back(&*proposal.candidate);
      }
      const size_t contenders = all.size();
      for (const ProposedCut& proposal : proposals) all.push_back(&state->candidates[proposal.base]);  // the baselines
      const std::vector<double> q = candidate_values(all, face_size, rules);
      const size_t pick = sample_softmax(std::vector<double>(q.begin(), q.begin() + static_cast<std::ptrdiff_t>(contenders)),
                                         temperature(), rng);
      chosen = all[pick]->action;
      // The actor's samples: each proposal's exact Q against the Q of the listed cut it turns.
      const double worst = *std::min_element(q.begin(), q.begin() + static_cast<std::ptrdiff_t>(listed.size()));
      size_t next = listed.size();
      for (size_t k = 0; k < proposals.size(); ++k) {
        const double value = proposals[k].candidate ? q[next++] : worst;
        proposal_samples.push_back(
            CutProposer::Sample{proposals[k].input, proposals[k].draw.z, (value - q[contenders + k]) / scale_});
      }
    }
    const double angle = std::uniform_real_distribution<double>(0.0, 2.0 * M_PI)(rng);
    const bool mirror = std::uniform_int_distribution<int>(0, 1)(rng) == 1;
    remember_region(part, face_size, rules, angle, mirror);
    episode.step(chosen);
    ++steps_;
    if (config_.learn_value && steps_ > config_.warmup_steps && memory_.size() >= static_cast<size_t>(config_.batch_size) &&
        steps_ % config_.update_every == 0) {
      lock.unlock();  // update takes it
      for (const auto& [name, value] : update(static_cast<size_t>(config_.batch_size), rng)) metric_sums[name] += value;
      lock.lock();
      ++updates;
    }
  }
  EpisodeRecord record = region_episode_record_of(episode, metric_sums, updates);
  record.alpha = temperature();
  if (proposer_ && !proposal_samples.empty()) {
    lock.unlock();
    for (const auto& [name, value] : proposer_->update(proposal_samples)) record.metrics[name] = value;
    int better = 0;  // proposals that beat the listed cut they turn
    for (const CutProposer::Sample& sample : proposal_samples) better += sample.advantage > 0.0;
    record.metrics["proposal_better"] = static_cast<double>(better) / static_cast<double>(proposal_samples.size());
  }
  return record;
}

std::unique_ptr<RegionPolicy> LookaheadAgent::deployed_region_policy(const std::string& name) {
  return std::make_unique<RegionLookaheadPolicy>(std::static_pointer_cast<LookaheadAgent>(shared_from_this()), name);
}

std::vector<float> LookaheadAgent::region_vertex_scores(const RegionEpisode& episode) {
  return RegionLookaheadPolicy(std::static_pointer_cast<LookaheadAgent>(shared_from_this()), "").vertex_scores(episode);
}

EpisodeRecord LookaheadAgent::train_episode(const GridFace& face, std::mt19937_64& rng, int max_steps) {
  EpisodeOptions options;
  options.reward = config_.reward;
  options.max_steps = max_steps;
  Episode episode(face, options);
  std::map<std::string, double> metric_sums;
  int updates = 0;
  while (episode.running()) {
    const auto state = cached_state(episode.current_part(), face.size);
    size_t chosen;
    if (steps_ < config_.warmup_steps) {
      chosen = std::uniform_int_distribution<size_t>(0, state->lines.size() - 1)(rng);
    } else {
      chosen = sample_softmax(cut_values(*state, face.size), temperature(), rng);
    }
    remember(episode.current_part(), face.size, std::uniform_int_distribution<int>(0, 7)(rng));
    const LineCandidate& line = state->lines[chosen];
    episode.step(Action{line.vertex, line.line.direction});
    ++steps_;
    if (config_.learn_value && steps_ > config_.warmup_steps && memory_.size() >= static_cast<size_t>(config_.batch_size) &&
        steps_ % config_.update_every == 0) {
      for (const auto& [name, value] : update(static_cast<size_t>(config_.batch_size), rng)) metric_sums[name] += value;
      ++updates;
    }
  }
  EpisodeRecord record = episode_record_of(episode, metric_sums, updates);
  record.alpha = temperature();
  return record;
}

std::map<std::string, double> LookaheadAgent::update(size_t count, std::mt19937_64& rng) {
  if (memory_.empty()) throw std::logic_error("LookaheadAgent::update: nothing remembered");
  std::uniform_int_distribution<size_t> pick(0, memory_.size() - 1);
  std::vector<const Memory*> batch;
  for (size_t k = 0; k < count; ++k) batch.push_back(&memory_[pick(rng)]);
  std::unique_lock<std::mutex> lock;  // general parts: the region engine's lock (region_policy.h)
  if (std::any_of(batch.begin(), batch.end(), [](const Memory* m) { return m->general(); })) lock = lock_general_engine();

  // Targets: soft maximum over each part's actions of reward + gamma * W'(pieces).
  struct Parent {
    std::shared_ptr<const PartState> state;
    const RegionPartState* general = nullptr;  // a general part's state (state, as a RegionPartState)
    std::vector<size_t> actions;               // general: the candidates valued
  };
  std::vector<Parent> parents;
  std::vector<const PartState*> missing;
  std::vector<GridKey> missing_parts;
  std::vector<RegionKey> missing_regions;
  std::vector<std::shared_ptr<const PartState>> keep;
  for (const Memory* m : batch) {
    Parent parent;
    if (!m->general()) {
      parent.state = cached_state(m->part, m->face_size);
      for (const LineCandidate& line : parent.state->lines) {
        for (const Part& piece : line.to_cut) {
          GridKey key{piece, m->face_size};
          if (target_values_.count(key)) continue;
          keep.push_back(cached_state(piece, m->face_size));
          missing.push_back(keep.back().get());
          target_values_[key] = 0.0;  // placeholder, filled below (also dedupes)
          missing_parts.push_back(std::move(key));
        }
      }
    } else {
      const auto state = cached_region_state(m->region, m->face_size, m->rules);
      parent.state = state;
      parent.general = state.get();
      parent.actions = best_candidates(state->candidates, static_cast<size_t>(config_.train_top_k));
      for (const size_t a : parent.actions) {
        for (const Region& piece : state->candidates[a].to_cut) {
          RegionKey key{piece, m->face_size, m->rules};
          if (region_target_values_.count(key)) continue;
          keep.push_back(cached_region_state(piece, m->face_size, m->rules));
          missing.push_back(keep.back().get());
          region_target_values_[key] = 0.0;
          missing_regions.push_back(std::move(key));
        }
      }
    }
    parents.push_back(std::move(parent));
  }
  if (!missing.empty()) {
    torch::NoGradGuard no_grad;
    const torch::Tensor w = forward_values(target_, missing).contiguous();
    const float* values = w.data_ptr<float>();
    size_t k = 0;
    for (const GridKey& key : missing_parts) target_values_[key] = values[k++];
    for (const RegionKey& key : missing_regions) region_target_values_[key] = values[k++];
  }
  const double alpha = temperature();
  std::vector<float> targets;
  double entropy = 0.0, entropy_target = 0.0;
  for (size_t b = 0; b < batch.size(); ++b) {
    const Parent& parent = parents[b];
    std::vector<double> q;
    if (!parent.general) {
      for (const LineCandidate& line : parent.state->lines) {
        double value = line.reward;
        for (const Part& piece : line.to_cut) value += config_.gamma * target_values_.at(GridKey{piece, batch[b]->face_size});
        q.push_back(value);
      }
    } else {
      for (const size_t a : parent.actions) {
        const RegionCandidate& candidate = parent.general->candidates[a];
        double value = candidate.reward;
        for (const Region& piece : candidate.to_cut) {
          value += config_.gamma * region_target_values_.at(RegionKey{piece, batch[b]->face_size, batch[b]->rules});
        }
        q.push_back(value);
      }
    }
    targets.push_back(static_cast<float>(soft_maximum(q, alpha)));
    entropy += softmax_entropy(q, alpha);
    entropy_target += config_.vertex_target_entropy_fraction * std::log(static_cast<double>(q.size()));
  }
  entropy /= static_cast<double>(batch.size());
  entropy_target /= static_cast<double>(batch.size());

  // The parts as presented: each in its remembered symmetry (grid) or turn and mirror (general).
  std::vector<std::shared_ptr<const PartState>> shown;
  std::vector<const PartState*> shown_raw;
  for (size_t k = 0; k < batch.size(); ++k) {
    const Memory& m = *batch[k];
    if (!m.general()) {
      shown.push_back(m.symmetry == 0 ? parents[k].state
                                      : make_part_state(transform_part(m.part, m.symmetry), state_options(m.face_size)));
    } else {
      const Region view = transform_region(m.region, m.angle, m.mirror);
      shown.push_back(view == m.region ? parents[k].state : cached_region_state(view, m.face_size, m.rules));
    }
    shown_raw.push_back(shown.back().get());
  }
  if (lock) lock.unlock();
  value_->train();
  const torch::Tensor w = forward_values(value_, shown_raw);
  const torch::Tensor y = torch::tensor(targets);
  const torch::Tensor loss = torch::mse_loss(w / scale_, y / scale_);
  value_optimizer_->zero_grad();
  loss.backward();
  torch::nn::utils::clip_grad_norm_(value_->parameters(), 10.0);
  value_optimizer_->step();

  const torch::Tensor temperature_loss = log_alpha_.exp() * (entropy - entropy_target);
  temperature_optimizer_->zero_grad();
  temperature_loss.backward();
  temperature_optimizer_->step();

  if (averaging()) update_average();
  if (++updates_ % config_.target_update_every == 0) {
    blend_module(*target_, *value_, 1.0);
    target_values_.clear();
    region_target_values_.clear();
  }
  if (target_values_.size() > 200000) target_values_.clear();
  if (region_target_values_.size() > 200000) region_target_values_.clear();
  return {{"value_loss", loss.item<double>()},
          {"alpha", temperature()},
          {"entropy", entropy},
          {"mean_target", y.mean().item<double>()},
          {"mean_value", w.mean().item<double>()}};
}

std::unique_ptr<Policy> LookaheadAgent::deployed_policy(const std::string& name) {
  return std::make_unique<LookaheadPolicy>(std::static_pointer_cast<LookaheadAgent>(shared_from_this()), name);
}

std::vector<float> LookaheadAgent::vertex_scores(const Episode& episode) {
  LookaheadPolicy policy(std::static_pointer_cast<LookaheadAgent>(shared_from_this()), "");  // fresh caches
  const auto state = policy.state_of(episode.current_part(), episode.face().size);
  const std::vector<double> q = policy.values(*state, episode.face().size);
  // A vertex scores the better of the cuts through it (lines through no other corner count too).
  std::vector<float> scores(episode.current_vertices().size(), -std::numeric_limits<float>::infinity());
  for (size_t v = 0; v < scores.size(); ++v) {
    const Corner& c = episode.current_vertices()[v].corner;
    for (size_t l = 0; l < state->lines.size(); ++l) {
      const AxisLine& line = state->lines[l].line;
      if ((line.direction == CutDirection::Vertical ? c.i : c.j) == line.index) {
        scores[v] = std::max(scores[v], static_cast<float>(q[l]));
      }
    }
  }
  return scores;
}

void LookaheadAgent::save(torch::serialize::OutputArchive& archive, bool training) const {
  // "value" is the deployed network; a checkpoint of an averaging run keeps the trained one too.
  torch::serialize::OutputArchive value;
  (averaging() ? average_ : value_)->save(value);
  archive.write("value", value);
  archive.write("log_alpha", log_alpha_.detach());
  if (proposer_) proposer_->save(archive, training);
  if (!training) return;
  if (averaging()) {
    torch::serialize::OutputArchive trained;
    value_->save(trained);
    archive.write("value_trained", trained);
  }
  torch::serialize::OutputArchive target, value_optimizer, temperature_optimizer;
  target_->save(target);
  archive.write("value_target", target);
  value_optimizer_->save(value_optimizer);
  archive.write("value_optimizer", value_optimizer);
  temperature_optimizer_->save(temperature_optimizer);
  archive.write("temperature_optimizer", temperature_optimizer);
  archive.write("counters", torch::tensor({static_cast<int64_t>(steps_), static_cast<int64_t>(updates_),
                                           static_cast<int64_t>(next_)}, torch::kInt64));
}

void LookaheadAgent::load(torch::serialize::InputArchive& archive, bool training) {
  torch::serialize::InputArchive value;
  archive.read("value", value);
  value_->load(value);
  if (averaging()) blend_module(*average_, *value_, 1.0);
  torch::Tensor log_alpha;
  archive.read("log_alpha", log_alpha);
  {
    torch::NoGradGuard no_grad;
    log_alpha_.copy_(log_alpha);
  }
  target_values_.clear();
  region_target_values_.clear();
  // A file trained without proposals (an initial policy for a run that trains them) leaves the
  // actor as it is; a checkpoint of this run always holds it.
  if (proposer_ && !proposer_->load(archive, training) && training) {
    throw InputError("the checkpoint holds no proposal actor (actor_candidates)");
  }
  if (!training) {
    blend_module(*target_, *value_, 1.0);
    return;
  }
  if (averaging()) {
    torch::serialize::InputArchive trained;
    archive.read("value_trained", trained);
    value_->load(trained);
  }
  torch::serialize::InputArchive target, value_optimizer, temperature_optimizer;
  archive.read("value_target", target);
  target_->load(target);
  archive.read("value_optimizer", value_optimizer);
  value_optimizer_->load(value_optimizer);
  archive.read("temperature_optimizer", temperature_optimizer);
  temperature_optimizer_->load(temperature_optimizer);
  torch::Tensor counters;
  archive.read("counters", counters);
  steps_ = counters[0].item<int64_t>();
  updates_ = counters[1].item<int64_t>();
  next_ = static_cast<size_t>(counters[2].item<int64_t>());
}

namespace {

void put_bytes(std::string& out, const void* data, size_t size) { out.append(static_cast<const char*>(data), size); }

template <typename T>
void put(std::string& out, const T& value) {
  put_bytes(out, &value, sizeof(T));
}

template <typename T>
T get(const std::string& in, size_t& offset) {
  if (offset + sizeof(T) > in.size()) throw InputError("corrupt replay memory (truncated)");
  T value;
  std::memcpy(&value, in.data() + offset, sizeof(T));
  offset += sizeof(T);
  return value;
}

constexpr std::uint32_t kMemoryMagic = 0x4d4c4241;    // "ABLM": grid parts only (before issue 12)
constexpr std::uint32_t kMemoryMagicV2 = 0x4e4c4241;  // "ABLN": each entry tagged grid (0) or general (1)

void put_ring(std::string& out, const Ring& ring) {
  put<std::uint64_t>(out, ring.size());
  for (const Point2& p : ring) {
    put(out, p.x);
    put(out, p.y);
  }
}

Ring get_ring(const std::string& in, size_t& offset) {
  const auto n = get<std::uint64_t>(in, offset);
  if (n < 3 || n > in.size()) throw InputError("corrupt replay memory (bad loop)");
  Ring ring(n);
  for (Point2& p : ring) {
    p.x = get<double>(in, offset);
    p.y = get<double>(in, offset);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError("corrupt replay memory (bad point)");
  }
  return ring;
}

}  // namespace

std::string LookaheadAgent::serialize_memory() const {
  std::string out;
  put(out, kMemoryMagicV2);
  std::map<const Grid*, std::uint32_t> grid_ids;
  std::vector<const Grid*> grids;
  for (const Memory& m : memory_) {
    if (m.general()) continue;
    if (grid_ids.emplace(&m.part.grid(), static_cast<std::uint32_t>(grids.size())).second) grids.push_back(&m.part.grid());
  }
  put<std::uint64_t>(out, grids.size());
  for (const Grid* g : grids) {
    put<std::uint64_t>(out, g->xs.size());
    put_bytes(out, g->xs.data(), g->xs.size() * sizeof(double));
    put<std::uint64_t>(out, g->ys.size());
    put_bytes(out, g->ys.data(), g->ys.size() * sizeof(double));
  }
  put<std::uint64_t>(out, memory_.size());
  for (const Memory& m : memory_) {
    put<std::uint8_t>(out, m.general() ? 1 : 0);
    if (m.general()) {
      put(out, m.face_size);
      put(out, m.angle);
      put<std::uint8_t>(out, m.mirror ? 1 : 0);
      put(out, m.rules.min_corner_degrees);
      put(out, m.rules.max_corner_degrees);
      put(out, m.rules.flat_tolerance_degrees);
      put(out, m.region.quantum());
      put<std::uint64_t>(out, m.region.holes().size());
      put_ring(out, m.region.outer());
      for (const Ring& hole : m.region.holes()) put_ring(out, hole);
      continue;
    }
    put(out, grid_ids.at(&m.part.grid()));
    put(out, m.face_size);
    put<std::int32_t>(out, m.symmetry);
    std::vector<std::int32_t> cells;
    for (int j = m.part.j0(); j < m.part.j0() + m.part.height_cells(); ++j) {
      for (int i = m.part.i0(); i < m.part.i0() + m.part.width_cells(); ++i) {
        if (m.part.contains(i, j)) {
          cells.push_back(i);
          cells.push_back(j);
        }
      }
    }
    put<std::uint64_t>(out, cells.size());
    put_bytes(out, cells.data(), cells.size() * sizeof(std::int32_t));
  }
  return out;
}

void LookaheadAgent::deserialize_memory(const std::string& in) {
  size_t offset = 0;
  const auto magic = get<std::uint32_t>(in, offset);
  if (magic != kMemoryMagic && magic != kMemoryMagicV2) throw InputError("corrupt replay memory (bad magic)");
  const bool tagged = magic == kMemoryMagicV2;
  const auto grid_count = get<std::uint64_t>(in, offset);
  if (grid_count > in.size()) throw InputError("corrupt replay memory (bad grid count)");
  std::vector<std::shared_ptr<const Grid>> grids;
  for (std::uint64_t g = 0; g < grid_count; ++g) {
    auto grid = std::make_shared<Grid>();
    for (std::vector<double>* axis : {&grid->xs, &grid->ys}) {
      const auto n = get<std::uint64_t>(in, offset);
      if (n < 2 || n > in.size()) throw InputError("corrupt replay memory (bad grid)");
      axis->resize(n);
      for (auto& v : *axis) v = get<double>(in, offset);
      if (!std::is_sorted(axis->begin(), axis->end())) throw InputError("corrupt replay memory (bad grid)");
    }
    grids.push_back(grid);
  }
  const auto count = get<std::uint64_t>(in, offset);
  if (count > static_cast<std::uint64_t>(config_.buffer_capacity)) throw InputError("corrupt replay memory (too many parts)");
  std::vector<Memory> memory;
  for (std::uint64_t k = 0; k < count; ++k) {
    const auto kind = tagged ? get<std::uint8_t>(in, offset) : std::uint8_t{0};
    if (kind > 1) throw InputError("corrupt replay memory (bad entry kind)");
    if (kind == 1) {
      Memory m;
      m.face_size = get<double>(in, offset);
      m.angle = get<double>(in, offset);
      m.mirror = get<std::uint8_t>(in, offset) != 0;
      m.rules.min_corner_degrees = get<double>(in, offset);
      m.rules.max_corner_degrees = get<double>(in, offset);
      m.rules.flat_tolerance_degrees = get<double>(in, offset);
      const double quantum = get<double>(in, offset);
      const auto holes = get<std::uint64_t>(in, offset);
      if (!(quantum > 0.0) || !(m.face_size > 0.0) || !std::isfinite(m.angle) || holes > in.size()) {
        throw InputError("corrupt replay memory (bad general part)");
      }
      const Ring outer = get_ring(in, offset);
      std::vector<Ring> hole_rings;
      for (std::uint64_t h = 0; h < holes; ++h) hole_rings.push_back(get_ring(in, offset));
      m.region = Region(outer, hole_rings, quantum);
      if (m.region.is_empty()) throw InputError("corrupt replay memory (empty general part)");
      memory.push_back(std::move(m));
      continue;
    }
    const auto grid = get<std::uint32_t>(in, offset);
    if (grid >= grids.size()) throw InputError("corrupt replay memory (bad grid index)");
    Memory m;
    m.face_size = get<double>(in, offset);
    m.symmetry = get<std::int32_t>(in, offset);
    const auto n = get<std::uint64_t>(in, offset);
    if (n == 0 || n % 2 || n > in.size() || m.symmetry < 0 || m.symmetry > 7) throw InputError("corrupt replay memory (bad part)");
    std::vector<std::pair<int, int>> cells;
    for (std::uint64_t c = 0; c < n; c += 2) {
      const int i = get<std::int32_t>(in, offset), j = get<std::int32_t>(in, offset);
      if (i < 0 || j < 0 || i >= grids[grid]->columns() || j >= grids[grid]->rows()) {
        throw InputError("corrupt replay memory (cell outside the grid)");
      }
      cells.emplace_back(i, j);
    }
    m.part = Part(grids[grid], cells);
    memory.push_back(std::move(m));
  }
  if (offset != in.size()) throw InputError("corrupt replay memory (trailing bytes)");
  memory_ = std::move(memory);
  region_states_.clear();
  region_target_values_.clear();
  if (memory_.size() < static_cast<size_t>(config_.buffer_capacity) ? next_ != 0 : next_ >= memory_.size()) {
    throw InputError("corrupt replay memory (bad position)");
  }
  states_.clear();
  target_values_.clear();
}

}  // namespace autoblock
