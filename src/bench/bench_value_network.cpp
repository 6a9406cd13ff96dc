// autoblock_bench_nn: what the value network costs when deployed. For the parts a decomposition
// meets (greedy's episodes on freshly generated faces of 2-10 and 11-40 rectangles, standing in for
// the learned policy's), times part_graph and the value network's forward pass (eval mode, no
// gradient) with 1 and 2 LibTorch threads (and OpenBLAS at its default or 1 thread), for every
// preset. Also prints the triangulations' sizes, compares SplineConv's two weighting kernels and
// times a training-like forward + backward on a batch. Prints Markdown; timings are reported,
// never asserted.
//
//   build/bin/autoblock_bench_nn --faces 100 --large-faces 30 --seed 7   (a few minutes on 2 cores)
//
// --graph refined|bounded picks part_graph's method (part_graph.h); --thin draws the faces of the
// size statistics on a bounded grid (2-10 rectangles: grid 32, sides 3-18; 11-40: grid 64, sides
// 4-24), where features one unit wide are common.
#include <CLI/CLI.hpp>
#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>

#include "bench/bench_stats.h"
#include "core/baselines/greedy_policy.h"
#include "core/data/thin_features.h"
#include "core/baselines/random_policy.h"
#include "core/data/shape_generator.h"
#include "core/env/episode.h"
#include "core/geometry/grid_face.h"
#include "core/graph/part_graph.h"
#include "core/nn/spline_basis.h"
#include "core/nn/spline_weighting.h"
#include "core/nn/tensor_convert.h"
#include "core/nn/threads.h"
#include "core/nn/value_network.h"

using namespace autoblock;

namespace {

GraphOptions graph_options;  // --graph

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

using bench::quantile;

double mean(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return v.empty() ? 0 : sum / static_cast<double>(v.size());
}

// The parts of one face's decomposition, in the order they are cut.
struct FaceParts {
  std::vector<Part> parts;
};

std::vector<FaceParts> greedy_parts(int count, std::uint64_t seed, const GeneratorOptions& options) {
  std::mt19937_64 rng(seed);
  std::vector<FaceParts> faces;
  for (int k = 0; k < count; ++k) {
    Episode episode(make_grid_face(generate_shape(rng, options).polygon));
    GreedyPolicy policy;
    FaceParts face;
    while (episode.running()) {
      face.parts.push_back(episode.current_part());
      episode.step(policy.choose(episode));
    }
    faces.push_back(std::move(face));
  }
  return faces;
}

void print_graph_sizes(const std::string& title, const std::vector<Part>& parts) {
  std::vector<double> nodes, edges, vertices;
  for (const Part& part : parts) {
    const PartGraph g = part_graph(part, graph_options);
    nodes.push_back(g.node_count());
    edges.push_back(g.edge_count() / 2.0);
    vertices.push_back(static_cast<double>(g.vertex_nodes.size()));
  }
  auto row = [](const char* what, const std::vector<double>& v) {
    std::printf("| | %s | %.1f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", what, mean(v), quantile(v, 0), quantile(v, 0.1),
                quantile(v, 0.5), quantile(v, 0.9), quantile(v, 1));
  };
  std::printf("| %s (%zu parts) | | | | | | | |\n", title.c_str(), parts.size());
  row("nodes", nodes);
  row("model vertices", vertices);
  row("undirected edges", edges);
}

void graph_statistics(std::uint64_t seed, bool thin) {
  std::printf("\n### Triangulation sizes (part_graph, %s graphs%s)\n\n", graph_method_name(graph_options.method),
              thin ? ", thin-feature faces" : "");
  std::printf("| set | quantity | mean | min | 10%% | median | 90%% | max |\n|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (bool holes : {false, true}) {
    for (auto [low, high] : {std::pair<int, int>{2, 10}, {11, 40}}) {
      const GeneratorOptions options = generator_kind_options(thin, low, high, holes);
      std::mt19937_64 rng(seed);
      std::vector<Part> faces, pieces;
      RandomPolicy policy(seed, /*splitting_only=*/true);
      for (int k = 0; k < 200; ++k) {
        Episode episode(make_grid_face(generate_shape(rng, options).polygon));
        faces.push_back(episode.current_part());
        while (episode.running()) {
          if (episode.steps() > 0) pieces.push_back(episode.current_part());
          episode.step(policy.choose(episode));
        }
      }
      const std::string name = std::to_string(low) + "-" + std::to_string(high) + " rectangles" +
                                (holes ? ", with holes" : "");
      print_graph_sizes("200 faces, " + name, faces);
      print_graph_sizes("cut pieces (random-split episodes), " + name, pieces);
    }
  }
}

void compare_kernels() {
  std::printf("\n### SplineConv weighting kernels, forward only, one layer (median us of 50)\n\n");
  std::printf("| nodes | in -> out | per-edge spline_weighting + mean | spline_mean_weighting (operator prebuilt) |\n");
  std::printf("|---:|---|---:|---:|\n");
  torch::manual_seed(0);
  torch::NoGradGuard no_grad;
  for (int64_t n : {40, 200}) {
    const int64_t e = 6 * n;
    const torch::Tensor edge_index = torch::stack({torch::randint(n, {e}, torch::kLong), torch::randint(n, {e}, torch::kLong)});
    const torch::Tensor pseudo = torch::rand({e, 2});
    const SplineGraph graph = spline_graph(edge_index, pseudo, n, 5);
    const auto [basis, index] = spline_basis(pseudo, 5);
    const torch::Tensor degree = torch::zeros({n}).index_add_(0, edge_index[1], torch::ones({e})).clamp_min(1).unsqueeze(1);
    for (auto [in, out] : {std::pair<int64_t, int64_t>{64, 128}, {128, 256}, {32, 16}}) {
      const torch::Tensor x = torch::randn({n, in}), weight = torch::randn({25, in, out});
      auto time = [](auto f) {
        std::vector<double> t;
        for (int r = 0; r < 53; ++r) {
          const auto start = Clock::now();
          f();
          if (r >= 3) t.push_back(1e3 * ms_since(start));
        }
        return quantile(t, 0.5);
      };
      const double per_edge = time([&] {
        const torch::Tensor m = spline_weighting(x, edge_index[0], weight, basis, index);
        return torch::zeros({n, out}).index_add_(0, edge_index[1], m) / degree;
      });
      const double fused = time([&] { return spline_mean_weighting(x, weight, graph); });
      std::printf("| %ld | %ld -> %ld | %.0f | %.0f |\n", static_cast<long>(n), static_cast<long>(in),
                  static_cast<long>(out), per_edge, fused);
    }
  }
}

// A thread set-up: LibTorch's intra-op threads and OpenBLAS's threads (0: OpenBLAS's default).
struct Threads {
  int torch = 1;
  int blas = 0;
};

std::string describe(const Threads& t, int blas_default) {
  return std::to_string(t.torch) + " / " + std::to_string(t.blas > 0 ? t.blas : blas_default) +
         (t.blas > 0 ? "" : " (default)");
}

void apply(const Threads& t, int blas_default) {
  torch::set_num_threads(t.torch);
  if (blas_default > 0) set_blas_threads(t.blas > 0 ? t.blas : blas_default);
}

void time_decompositions(const std::string& title, const std::vector<FaceParts>& faces, int repeats,
                         const std::vector<Threads>& setups, int blas_default) {
  std::printf("\n### %s: %zu faces\n\n", title.c_str(), faces.size());
  size_t parts = 0;
  std::vector<double> steps;
  for (const FaceParts& f : faces) {
    parts += f.parts.size();
    steps.push_back(static_cast<double>(f.parts.size()));
  }
  std::printf("Parts triangulated per face (greedy's cuts): mean %.1f, median %.0f, max %.0f; %zu parts in all.\n\n",
              mean(steps), quantile(steps, 0.5), quantile(steps, 1), parts);
  std::printf("| preset | threads (torch / BLAS) | graph ms / part (median) | forward ms / part (median) | (90%%) | "
              "graph + forward ms / face (median) | (90%%) | (max) |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& name : ValueNetworkConfig::names()) {
    torch::manual_seed(1);
    ValueNetwork net(ValueNetworkConfig::by_name(name));
    net->eval();
    for (const Threads& setup : setups) {
      apply(setup, blas_default);
      torch::NoGradGuard no_grad;
      // Warm up allocators and thread pools.
      for (int k = 0; k < 5; ++k) {
        const PartGraph g = part_graph(faces[0].parts[0], graph_options);
        const GraphBatch b = graph_batch_of(g);
        net(b.x, b.edge_index, b.pseudo);
      }
      std::vector<double> graph_ms, forward_ms, face_ms;
      for (const FaceParts& face : faces) {
        double best = 1e30;
        for (int r = 0; r < repeats; ++r) {
          double total = 0;
          for (const Part& part : face.parts) {
            auto start = Clock::now();
            const PartGraph g = part_graph(part, graph_options);
            const double graph_time = ms_since(start);
            start = Clock::now();
            const GraphBatch b = graph_batch_of(g);
            const torch::Tensor values = net(b.x, b.edge_index, b.pseudo);
            const int64_t chosen = vertex_values(values, b).argmax().item<int64_t>();
            (void)chosen;
            const double forward_time = ms_since(start);
            if (r == 0) {
              graph_ms.push_back(graph_time);
              forward_ms.push_back(forward_time);
            }
            total += graph_time + forward_time;
          }
          best = std::min(best, total);
        }
        face_ms.push_back(best);
      }
      std::printf("| %s | %s | %.3f | %.3f | %.3f | %.2f | %.2f | %.2f |\n", name.c_str(),
                  describe(setup, blas_default).c_str(), quantile(graph_ms, 0.5), quantile(forward_ms, 0.5),
                  quantile(forward_ms, 0.9), quantile(face_ms, 0.5), quantile(face_ms, 0.9), quantile(face_ms, 1));
    }
  }
}

// A training-like step: forward and backward (train mode) on a batch of graphs of cut pieces.
void time_training_steps(const std::vector<FaceParts>& faces, int batch_size, const std::vector<Threads>& setups,
                         int blas_default) {
  std::vector<PartGraph> graphs;
  for (const FaceParts& f : faces) {
    for (const Part& p : f.parts) {
      if (static_cast<int>(graphs.size()) < batch_size) graphs.push_back(part_graph(p, graph_options));
    }
  }
  std::vector<const PartGraph*> pointers;
  for (const PartGraph& g : graphs) pointers.push_back(&g);
  const GraphBatch batch = batch_graphs(pointers);
  std::printf("\n### Forward + backward, train mode, one batch of %zu part graphs (%ld nodes): median ms of 10\n\n",
              graphs.size(), static_cast<long>(batch.node_count()));
  std::printf("| preset | threads (torch / BLAS) | ms / step |\n|---|---|---:|\n");
  for (const std::string& name : ValueNetworkConfig::names()) {
    torch::manual_seed(2);
    ValueNetwork net(ValueNetworkConfig::by_name(name));
    net->train();
    const torch::Tensor probe = torch::randn({batch.vertex_nodes.size(0)});
    for (const Threads& setup : setups) {
      apply(setup, blas_default);
      std::vector<double> ms;
      for (int r = 0; r < 12; ++r) {
        const auto start = Clock::now();
        net->zero_grad();
        const torch::Tensor values = net(batch.x, batch.edge_index, batch.pseudo);
        (vertex_values(values, batch) * probe).sum().backward();
        if (r >= 2) ms.push_back(ms_since(start));
      }
      std::printf("| %s | %s | %.1f |\n", name.c_str(), describe(setup, blas_default).c_str(), quantile(ms, 0.5));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Time part_graph and the value network's forward pass as deployed."};
  int faces = 100, large_faces = 30, repeats = 1, batch = 64;
  std::uint64_t seed = 7;
  bool skip_sizes = false, skip_kernels = false, thin = false, skip_timing = false;
  std::string method = "bounded";
  app.add_option("--faces", faces, "generated 2-10 rectangle faces")->capture_default_str();
  app.add_option("--large-faces", large_faces, "generated 11-40 rectangle faces")->capture_default_str();
  app.add_option("--seed", seed, "generator seed")->capture_default_str();
  app.add_option("--repeats", repeats, "runs per face (the fastest counts for the per-face total)")->capture_default_str();
  app.add_option("--batch", batch, "graphs in the training-step timing (0: skip it)")->capture_default_str();
  app.add_flag("--skip-sizes", skip_sizes, "do not print the triangulation sizes");
  app.add_flag("--skip-kernels", skip_kernels, "do not compare the weighting kernels");
  app.add_flag("--skip-timing", skip_timing, "do not time decompositions and training steps");
  app.add_flag("--thin", thin, "triangulation sizes on thin-feature faces (bounded grid)");
  app.add_option("--graph", method, "graph method: bounded or refined")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const char* blas_env = std::getenv("OPENBLAS_NUM_THREADS");
    std::printf("LibTorch %s, default intra-op threads %d, OPENBLAS_NUM_THREADS=%s\n", TORCH_VERSION,
                torch::get_num_threads(), blas_env ? blas_env : "(unset)");
    const int blas_default = blas_threads();
    std::printf("OpenBLAS threads by default: %d (-1: the BLAS is not OpenBLAS)\n", blas_default);
    graph_options.method = graph_method_by_name(method);
    if (!skip_sizes) graph_statistics(seed, thin);
    if (!skip_kernels) compare_kernels();
    if (skip_timing) return 0;
    std::vector<Threads> setups{{1, 0}, {2, 0}};
    if (blas_default > 0) setups.insert(setups.end(), {Threads{1, 1}, Threads{2, 1}});
    GeneratorOptions small;
    const std::vector<FaceParts> small_faces = greedy_parts(faces, seed, small);
    time_decompositions("Generated 2-10 rectangle faces, seed " + std::to_string(seed), small_faces, repeats, setups,
                        blas_default);
    GeneratorOptions large;
    large.min_rects = 11;
    large.max_rects = 40;
    time_decompositions("Generated 11-40 rectangle faces, seed " + std::to_string(seed),
                        greedy_parts(large_faces, seed, large), repeats, setups, blas_default);
    if (batch > 0) time_training_steps(small_faces, batch, setups, blas_default);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
