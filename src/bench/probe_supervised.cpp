// autoblock_probe: what the networks can represent, measured by supervised learning on exact
// targets (a research probe, not part of the product). For parts met while decomposing the training
// faces, the exact action values Q*(P, v, a) = reward + sum of the optimal values of the pieces come
// from the exact search; the value network then regresses them and the actor classifies the better
// direction; the trained networks decompose the test faces deterministically.
//   mode paper: value network with one output per vertex (max_a Q*), actor on the 9 numbers
//   mode pair:  value network with two outputs per vertex (Q* of each direction)
#include <CLI/CLI.hpp>

#include <torch/torch.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <set>
#include <unordered_set>

#include "core/baselines/baseline_policy.h"
#include "core/baselines/optimal_search.h"
#include "core/geometry/part_symmetry.h"
#include "core/env/decomposition.h"
#include "core/io/dataset.h"
#include "core/io/input_face.h"
#include "core/nn/graph_batch.h"
#include "core/nn/mlp.h"
#include "core/nn/tensor_convert.h"
#include "core/nn/threads.h"
#include "core/nn/value_network.h"
#include "core/sac/part_state.h"

using namespace autoblock;

namespace {

struct Sample {
  std::shared_ptr<const PartState> state;
  std::vector<std::array<float, 9>> lookahead;  // per vertex: reflex, r_h/10, r_v/10, N_h/4, N_v/4, Nq_h/N_h, Nq_v/N_v
  std::vector<std::array<float, 2>> q;      // Q*(v, a) / scale
  std::vector<std::array<char, 2>> splits;  // does (v, a) split the part
  float value = 0;                          // V*(P) / scale
};

constexpr float kScale = 10.0f;
bool g_lookahead = false;
int g_symmetries = 1;

std::vector<std::array<float, 9>> lookahead_of(const Episode& episode) {
  std::vector<std::array<float, 9>> features;
  for (int v = 0; v < static_cast<int>(episode.current_vertices().size()); ++v) {
    std::array<float, 9> f{};
    f[0] = episode.current_vertices()[static_cast<size_t>(v)].corner.reflex ? 1.f : 0.f;
    for (int a = 0; a < 2; ++a) {
      const auto pieces = episode.pieces_of(Action{v, static_cast<CutDirection>(a)});
      int rect = 0;
      for (const Part& p : pieces) rect += p.is_rectangle();
      f[static_cast<size_t>(1 + a)] = static_cast<float>(episode.reward_of(pieces)) / kScale;
      f[static_cast<size_t>(3 + a)] = static_cast<float>(pieces.size()) / 4.f;
      f[static_cast<size_t>(5 + a)] = static_cast<float>(rect) / static_cast<float>(pieces.size());
    }
    const Box box = episode.current_part().bbox();
    f[7] = static_cast<float>(box.longer_side() / episode.face().size);
    f[8] = static_cast<float>(std::sqrt(episode.current_part().area()) / episode.face().size);
    features.push_back(f);
  }
  return features;
}

// Node features: the graph's one-hot kinds, plus the vertices' lookahead when enabled.
torch::Tensor node_features(const GraphBatch& b, const std::vector<const std::vector<std::array<float, 9>>*>& lookahead) {
  if (!g_lookahead) return b.x;
  torch::Tensor extra = torch::zeros({b.x.size(0), 9});
  for (size_t g = 0; g < lookahead.size(); ++g) {
    for (int64_t n = b.node_offsets[g]; n < b.node_offsets[g + 1]; ++n) {
      extra[n][7] = (*lookahead[g])[0][7];
      extra[n][8] = (*lookahead[g])[0][8];
    }
    for (size_t v = 0; v < lookahead[g]->size(); ++v) {
      const int64_t node = b.vertex_nodes[b.vertex_offsets[g] + static_cast<int64_t>(v)].item<int64_t>();
      for (int k = 0; k < 7; ++k) extra[node][k] = (*lookahead[g])[v][static_cast<size_t>(k)];
    }
  }
  return torch::cat({b.x, extra}, 1);
}

std::vector<Sample> collect(const std::vector<GridFace>& faces, int episodes_per_face, std::mt19937_64& rng) {
  std::vector<Sample> samples;
  for (const GridFace& face : faces) {
    OptimalSearch search(face.size, 0);
    std::unordered_set<Part, PartHash> seen;
    for (int e = 0; e < episodes_per_face; ++e) {
      BaselineOptions options;
      options.seed = rng();
      auto policy = make_baseline_policy(e == 0 ? "optimal" : "random-split", face.size, options);
      Episode episode(face);
      while (episode.running()) {
        const Part& part = episode.current_part();
        if (seen.insert(part).second) {
          for (int sym = 0; sym < g_symmetries; ++sym) {
          const Part image = transform_part(part, sym);
          Episode view(GridFace{image.grid_ptr(), image, face.size});
          Sample s;
          s.state = make_part_state(image, GraphOptions{});
          s.lookahead = lookahead_of(view);
          s.value = static_cast<float>(search.value(part)) / kScale;
          for (int v = 0; v < static_cast<int>(episode.current_vertices().size()); ++v) {
            std::array<float, 2> q{};
            std::array<char, 2> split{};
            for (int a = 0; a < 2; ++a) {
              const Action action{v, static_cast<CutDirection>(a)};
              const auto pieces = episode.pieces_of(action);
              double value = episode.reward_of(pieces);
              for (const Part& piece : pieces) value += search.value(piece);
              split[static_cast<size_t>(a)] = pieces.size() > 1;
              q[static_cast<size_t>(a)] = static_cast<float>(value) / kScale;
            }
            s.q.push_back(q);
            s.splits.push_back(split);
          }
          if (sym > 0) s.q.clear(), s.splits.clear();
          samples.push_back(std::move(s));
          }
        }
        episode.step(policy->choose(episode));
      }
    }
  }
  return samples;
}

struct Model {
  ValueNetwork value{nullptr};
  Mlp actor{nullptr};
  bool pair = false;
  bool afterstate = false;
};

// State value of each part: the sum of the network's outputs at its model vertices.
torch::Tensor state_values(Model& model, const std::vector<const PartGraph*>& graphs,
                           const std::vector<const std::vector<std::array<float, 9>>*>& looks) {
  const GraphBatch b = batch_graphs(graphs);
  const torch::Tensor out = model.value->forward(node_features(b, looks), b.edge_index, b.pseudo).index_select(0, b.vertex_nodes);
  std::vector<int64_t> owner;
  for (size_t g = 0; g + 1 < b.vertex_offsets.size(); ++g) {
    for (int64_t k = b.vertex_offsets[g]; k < b.vertex_offsets[g + 1]; ++k) owner.push_back(static_cast<int64_t>(g));
  }
  return torch::zeros({static_cast<int64_t>(graphs.size())}).index_add(0, torch::tensor(owner), out);
}

double deploy_afterstate(Model& model, const std::vector<GridFace>& faces) {
  model.value->eval();
  torch::NoGradGuard no_grad;
  double total = 0;
  for (const GridFace& face : faces) {
    Episode episode(face);
    while (episode.running()) {
      std::vector<Action> actions;
      std::vector<double> rewards;
      std::vector<std::vector<int>> kids;
      std::vector<std::shared_ptr<const PartState>> states;
      std::vector<const PartGraph*> graphs;
      std::vector<std::unique_ptr<std::vector<std::array<float, 9>>>> look_store;
      std::vector<const std::vector<std::array<float, 9>>*> looks;
      std::set<std::pair<int, int>> lines;
      for (int v = 0; v < static_cast<int>(episode.current_vertices().size()); ++v) {
        for (int a = 0; a < 2; ++a) {
          const Action action{v, static_cast<CutDirection>(a)};
          const AxisLine line = episode.line_of(action);
          if (!lines.insert({a, line.index}).second) continue;
          if (!line_crosses_interior(episode.current_part(), line)) continue;
          const auto pieces = episode.pieces_of(action);
          actions.push_back(action);
          rewards.push_back(episode.reward_of(pieces));
          kids.emplace_back();
          for (const Part& p : pieces) {
            if (p.is_rectangle()) continue;
            states.push_back(make_part_state(p, GraphOptions{}));
            graphs.push_back(&states.back()->graph);
            if (g_lookahead) {
              EpisodeOptions eo;
              Episode sub(GridFace{face.grid, p, face.size}, eo);
              look_store.push_back(std::make_unique<std::vector<std::array<float, 9>>>(lookahead_of(sub)));
              looks.push_back(look_store.back().get());
            }
            kids.back().push_back(static_cast<int>(graphs.size()) - 1);
          }
        }
      }
      torch::Tensor w = graphs.empty() ? torch::zeros({0}) : state_values(model, graphs, looks);
      double best = -1e30;
      Action chosen = actions[0];
      for (size_t k = 0; k < actions.size(); ++k) {
        double q = rewards[k];
        for (int c : kids[k]) q += kScale * w[c].item<double>();
        if (q > best) {
          best = q;
          chosen = actions[k];
        }
      }
      episode.step(chosen);
    }
    total += episode.total_return();
  }
  return total / static_cast<double>(faces.size());
}

double deploy(Model& model, const std::vector<GridFace>& faces) {
  if (model.afterstate) return deploy_afterstate(model, faces);
  model.value->eval();
  torch::NoGradGuard no_grad;
  double total = 0;
  for (const GridFace& face : faces) {
    Episode episode(face);
    while (episode.running()) {
      const auto state = make_part_state(episode.current_part(), GraphOptions{});
      const GraphBatch b = batch_graphs({&state->graph});
      const auto look = lookahead_of(episode);
      const torch::Tensor out = model.value->forward(node_features(b, {&look}), b.edge_index, b.pseudo).index_select(0, b.vertex_nodes);
      double best = -1e30;
      Action chosen{-1, CutDirection::Horizontal};
      for (int v = 0; v < static_cast<int>(state->observations.size()); ++v) {
        for (int a = 0; a < 2; ++a) {
          const Action action{v, static_cast<CutDirection>(a)};
          if (!line_crosses_interior(episode.current_part(), episode.line_of(action))) continue;
          double score;
          if (model.pair) {
            score = out[v][a].item<double>();
          } else {
            const torch::Tensor logits = model.actor->forward(observations_tensor({state->observations[static_cast<size_t>(v)]}));
            const int preferred = logits[0][1].item<float>() > logits[0][0].item<float>() ? 1 : 0;
            score = out[v].item<double>() - (a == preferred ? 0.0 : 1e6);  // the actor's direction first
          }
          if (score > best) {
            best = score;
            chosen = action;
          }
        }
      }
      episode.step(chosen);
    }
    total += episode.total_return();
  }
  return total / static_cast<double>(faces.size());
}

double mean_optimal(const std::vector<GridFace>& faces) {
  double total = 0;
  for (const GridFace& f : faces) total += OptimalSearch(f.size, 0).value(f.whole);
  return total / static_cast<double>(faces.size());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Supervised probe of the networks' capacity."};
  std::string train_dir = "models/data/train", test_dir = "models/data/test", mode = "paper", preset = "small";
  int extra = 200, epochs = 30, episodes = 4;
  app.add_option("--train", train_dir);
  app.add_option("--test", test_dir);
  app.add_option("--mode", mode)->check(CLI::IsMember({"paper", "pair", "afterstate"}));
  app.add_option("--value-network", preset);
  app.add_option("--extra", extra, "extra generated training faces");
  app.add_option("--epochs", epochs);
  app.add_option("--episodes", episodes, "episodes per training face to collect parts");
  app.add_flag("--lookahead", g_lookahead, "add one-step lookahead features at the vertices");
  app.add_option("--symmetries", g_symmetries, "augment with this many of the square's symmetries (afterstate mode)");
  CLI11_PARSE(app, argc, argv);
  torch::manual_seed(1);
  torch::set_num_threads(1);
  set_blas_threads(1);
  std::mt19937_64 rng(1);
  std::vector<GridFace> train, test;
  for (const auto& f : collect_shape_files({train_dir})) train.push_back(load_input_face(f).grid);
  for (const auto& f : collect_shape_files({test_dir})) test.push_back(load_input_face(f).grid);
  for (int k = 0; k < extra; ++k) train.push_back(make_grid_face(generate_shape(rng, {}).polygon));
  std::vector<GridFace> fresh;
  std::mt19937_64 fresh_rng(777);
  for (int k = 0; k < 100; ++k) fresh.push_back(make_grid_face(generate_shape(fresh_rng, {}).polygon));

  const std::vector<Sample> samples = collect(train, episodes, rng);
  std::printf("%zu parts from %zu faces\n", samples.size(), train.size());
  Model model;
  model.pair = mode == "pair";
  model.afterstate = mode == "afterstate";
  ValueNetworkConfig config = ValueNetworkConfig::by_name(preset);
  config.outputs = model.pair ? 2 : 1;
  config.inputs = g_lookahead ? 12 : 3;
  model.value = ValueNetwork(config);
  model.actor = Mlp(9, std::vector<int64_t>{256, 128, 64}, 2, false);
  torch::optim::Adam value_opt(model.value->parameters(), torch::optim::AdamOptions(1e-3));
  torch::optim::Adam actor_opt(model.actor->parameters(), torch::optim::AdamOptions(1e-3));
  std::vector<size_t> order(samples.size());
  std::iota(order.begin(), order.end(), 0);
  const double optimal_test = mean_optimal(test), optimal_fresh = mean_optimal(fresh);
  for (int epoch = 1; epoch <= epochs; ++epoch) {
    std::shuffle(order.begin(), order.end(), rng);
    double value_loss = 0, actor_loss = 0;
    int batches = 0;
    model.value->train();
    for (size_t start = 0; start + 32 <= order.size(); start += 32) {
      std::vector<const PartGraph*> graphs;
      std::vector<const std::vector<std::array<float, 9>>*> looks;
      std::vector<float> targets;
      std::vector<Observation> obs;
      std::vector<int64_t> labels;
      std::vector<float> weights;
      for (size_t k = start; k < start + 32; ++k) {
        const Sample& s = samples[order[k]];
        graphs.push_back(&s.state->graph);
        looks.push_back(&s.lookahead);
        for (size_t v = 0; v < s.q.size(); ++v) {
          if (model.pair) {
            targets.push_back(s.q[v][0]);
            targets.push_back(s.q[v][1]);
          } else {
            targets.push_back(std::max(s.q[v][0], s.q[v][1]));
          }
          obs.push_back(s.state->observations[v]);
          labels.push_back(s.q[v][1] > s.q[v][0] ? 1 : 0);
          weights.push_back(std::fabs(s.q[v][1] - s.q[v][0]));
        }
      }
      if (model.afterstate) {
        std::vector<float> values;
        for (size_t k = start; k < start + 32; ++k) values.push_back(samples[order[k]].value);
        const torch::Tensor loss = torch::mse_loss(state_values(model, graphs, looks), torch::tensor(values));
        value_opt.zero_grad();
        loss.backward();
        value_opt.step();
        value_loss += loss.item<double>();
        ++batches;
        continue;
      }
      const GraphBatch b = batch_graphs(graphs);
      torch::Tensor out = model.value->forward(node_features(b, looks), b.edge_index, b.pseudo).index_select(0, b.vertex_nodes).reshape({-1});
      const torch::Tensor target = torch::tensor(targets);
      const torch::Tensor loss = torch::mse_loss(out, target);
      value_opt.zero_grad();
      loss.backward();
      value_opt.step();
      value_loss += loss.item<double>();
      if (!model.pair) {
        const torch::Tensor logits = model.actor->forward(observations_tensor(obs));
        const torch::Tensor ce = torch::nn::functional::cross_entropy(
            logits, torch::tensor(labels), torch::nn::functional::CrossEntropyFuncOptions().reduction(torch::kNone));
        const torch::Tensor aloss = (ce * torch::tensor(weights)).mean();
        actor_opt.zero_grad();
        aloss.backward();
        actor_opt.step();
        actor_loss += aloss.item<double>();
      }
      ++batches;
    }
    if (epoch % 5 == 0 || epoch == epochs) {
      const double t = deploy(model, test), f = deploy(model, fresh);
      std::printf("epoch %d: value loss %.4f actor loss %.4f | test %.3f (%.3f of optimal) | fresh %.3f (%.3f)\n", epoch,
                  value_loss / batches, actor_loss / batches, t, t / optimal_test, f, f / optimal_fresh);
      std::fflush(stdout);
    }
  }
  return 0;
}
