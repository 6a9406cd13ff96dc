// autoblock eval DIR_OR_FILES... [--face N] [--policy NAME] [--json out.json] [--seed S] [--threads T]
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "core/api/face_actions.h"
#include "core/common/error.h"
#include "core/common/format.h"
#include "cli/commands.h"
#include "cli/progress_bar.h"
#include "core/io/dataset.h"
#include "core/io/decomposition_json.h"
#include "core/io/text_file.h"

namespace autoblock::cli {
namespace {

nlohmann::json statistics(std::vector<double> values) {
  if (values.empty()) return {{"mean", nullptr}, {"median", nullptr}, {"total", 0.0}};
  double total = 0.0;
  for (double v : values) total += v;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  return {{"mean", total / static_cast<double>(n)}, {"median", median}, {"total", total}};
}

}  // namespace

void add_eval_command(CLI::App& app) {
  struct Arguments {
    std::vector<std::string> paths;
    std::string json;
    int threads = 0;
    PolicyArguments policy;
    FaceArguments face;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("eval", "Decompose a set of faces and report per-shape and overall figures.");
  command->add_option("DIR_OR_FILES", args->paths, "folders of .brep/.step/.stp files, or files")->required();
  args->face.add_to(*command);
  args->policy.add_to(*command);
  command->add_option("--json", args->json, "write per-shape reports and the summary as JSON");
  command->add_option("--threads", args->threads, "worker threads (0: one per core)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  command->callback([args] {
    // Read and check every input before any work, so bad input stops the run at once.
    const std::vector<std::string> files = collect_shape_files(args->paths);
    std::vector<InputFace> faces;
    for (const std::string& file : files) faces.push_back(args->face.load(file));
    // The grid engine's policy is loaded (or said to be unknown) when some face is rectilinear; the
    // general engine takes its own names (general_policy_names()).
    const bool any_grid = std::any_of(faces.begin(), faces.end(), [](const InputFace& f) { return !f.is_general(); });
    const std::string policy_name =
        any_grid ? args->policy.source()->name() : (args->policy.policy.empty() ? "auto" : args->policy.policy);

    std::vector<Decomposition> results(faces.size());
    std::vector<RegionDecomposition> general(faces.size());  // faces with edges at other angles (core/api)
    std::vector<std::string> errors(faces.size());
    std::atomic<size_t> next{0}, done{0};
    const EpisodeOptions options = any_grid ? args->policy.episode_options() : EpisodeOptions{};
    auto work = [&] {
      for (size_t k = next++; k < faces.size(); k = next++) {
        try {
          if (faces[k].is_general()) {
            // The policy itself, one search (not mesh's tries, which mesh every decomposition).
            DecomposeSettings settings = args->policy.decompose_settings(k);
            settings.mesh_tries = false;
            general[k] = decompose_input_face(faces[k], settings).region;
          } else {
            std::unique_ptr<Policy> policy = args->policy.make(faces[k], k);
            results[k] = decompose_face(faces[k].grid, *policy, options);
          }
        } catch (const std::exception& e) {
          errors[k] = e.what();  // a learned policy on a general face: said after the workers stop
        }
        ++done;
      }
    };
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const size_t thread_count =
        std::min(faces.size(), static_cast<size_t>(args->threads > 0 ? static_cast<unsigned>(args->threads) : hardware));
    // Parallelism comes from the workers: a learned policy computes on one thread (learned_runtime.h).
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (size_t t = 0; t < thread_count; ++t) workers.emplace_back(work);
    {
      ProgressBar progress(static_cast<long>(faces.size()), "eval " + policy_name);
      while (done < faces.size()) {
        progress.update(static_cast<long>(done), files[std::min(done.load(), faces.size() - 1)]);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    }
    for (std::thread& worker : workers) worker.join();
    for (size_t k = 0; k < faces.size(); ++k) {
      if (!errors[k].empty()) throw InputError(files[k] + ": " + errors[k]);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    nlohmann::json report = {{"policy", policy_name},
                             {"files", files.size()}};
    report["shapes"] = nlohmann::json::array();
    std::vector<double> returns, blocks, minimum, ratio, seconds, cuts, templates;
    size_t complete = 0, truncated = 0, capped = 0, general_faces = 0;
    std::printf("%7s %7s %6s %10s %-10s %9s  %s\n", "blocks", "minimum", "cuts", "return", "status", "ms", "file");
    for (size_t k = 0; k < faces.size(); ++k) {
      if (faces[k].is_general()) {
        // Blocks and templates of the general engine; no minimum (it is known on rectilinear faces only).
        const RegionDecomposition& g = general[k];
        report["shapes"].push_back(region_decomposition_json(files[k], faces[k], g));
        returns.push_back(g.total_return);
        blocks.push_back(static_cast<double>(g.blocks));
        templates.push_back(static_cast<double>(g.templates));
        seconds.push_back(g.seconds);
        cuts.push_back(static_cast<double>(g.cuts.size()));
        complete += g.complete();
        truncated += g.status == EpisodeStatus::Truncated;
        capped += g.time_capped;
        ++general_faces;
        std::printf("%7s %7s %6zu %10.3f %-10s %9.2f  %s\n",
                    (std::to_string(g.blocks) + (g.templates ? "+" + std::to_string(g.templates) + "t" : "")).c_str(), "-",
                    g.cuts.size(), g.total_return, status_name(g.status).c_str(), g.seconds * 1000.0, files[k].c_str());
        continue;
      }
      const Decomposition& d = results[k];
      report["shapes"].push_back(decomposition_json(files[k], faces[k].planar, d));
      returns.push_back(d.total_return);
      blocks.push_back(static_cast<double>(d.blocks.size()));
      minimum.push_back(d.min_blocks);
      ratio.push_back(static_cast<double>(d.blocks.size()) / d.min_blocks);
      seconds.push_back(d.seconds);
      cuts.push_back(static_cast<double>(d.cuts.size()));
      complete += d.complete();
      truncated += d.truncated();
      capped += d.time_capped;
      std::printf("%7zu %7d %6zu %10.3f %-10s %9.2f  %s\n", d.blocks.size(), d.min_blocks, d.cuts.size(), d.total_return,
                  status_name(d.status).c_str(), d.seconds * 1000.0, files[k].c_str());
    }
    const nlohmann::json time = statistics(seconds);
    const double total_cuts = statistics(cuts)["total"].get<double>();
    report["summary"] = {
        {"return", statistics(returns)},
        {"blocks", statistics(blocks)},
        {"min_blocks", statistics(minimum)},
        {"blocks_over_min", statistics(ratio)},
        {"cuts", statistics(cuts)},
        {"seconds", time},
        {"seconds_per_cut", total_cuts > 0 ? time["total"].get<double>() / total_cuts : 0.0},
        {"complete", complete},
        {"truncated", truncated},
        {"time_capped", capped},
        {"general_faces", general_faces},  // by the general engine: blocks and templates, no minimum
        {"templates", statistics(templates)},
        {"completion_rate", faces.empty() ? 0.0 : static_cast<double>(complete) / static_cast<double>(faces.size())},
        {"wall_seconds", wall},
        {"threads", thread_count}};
    const nlohmann::json& s = report["summary"];
    if (minimum.empty()) {
      std::printf("\n%s on %s (general engine): return mean %.3f median %.3f; blocks mean %.2f, templates mean %.2f; "
                  "complete %zu/%zu%s; %.2f ms per shape\n",
                  report["policy"].get<std::string>().c_str(), counted(static_cast<long long>(faces.size()), "shape").c_str(),
                  s["return"]["mean"].get<double>(), s["return"]["median"].get<double>(), s["blocks"]["mean"].get<double>(),
                  s["templates"]["mean"].is_null() ? 0.0 : s["templates"]["mean"].get<double>(), complete, faces.size(),
                  capped ? (", " + std::to_string(capped) + " hit the time limit").c_str() : "",
                  s["seconds"]["mean"].get<double>() * 1000.0);
    } else {
    std::printf("\n%s on %s: return mean %.3f median %.3f; blocks mean %.2f (minimum %.2f, ratio %.3f); "
                "complete %zu/%zu%s; %.2f ms per shape, %.3f ms per cut\n",
                report["policy"].get<std::string>().c_str(), counted(static_cast<long long>(faces.size()), "shape").c_str(), s["return"]["mean"].get<double>(),
                s["return"]["median"].get<double>(), s["blocks"]["mean"].get<double>(),
                s["min_blocks"]["mean"].get<double>(), s["blocks_over_min"]["mean"].get<double>(), complete, faces.size(),
                capped ? (", " + std::to_string(capped) + " hit the time limit").c_str() : "",
                s["seconds"]["mean"].get<double>() * 1000.0, s["seconds_per_cut"].get<double>() * 1000.0);
      if (general_faces > 0) std::printf("(%zu of the shapes by the general engine: their blocks count, not in the minimum)\n", general_faces);
    }
    if (!args->json.empty()) {
      write_text_file(args->json, report.dump(2) + "\n");
      std::printf("report: %s\n", args->json.c_str());
    }
  });
}

}  // namespace autoblock::cli
