// Pieces shared by the commands: policy options and summaries.
#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "core/api/catalog.h"
#include "core/env/decomposition.h"
#include "core/env/episode.h"
#include "core/io/input_face.h"

namespace autoblock::cli {

// The options every command that runs a policy takes.
struct PolicyArguments {
  std::string policy = default_policy_name();
  std::uint64_t seed = 0;
  int max_steps = 0;
  double time_limit = 30.0;

  void add_to(CLI::App& command);
  // Inputs: face; shape_index, added to the seed so that each shape of a set has its own stream.
  std::unique_ptr<Policy> make(const InputFace& face, std::uint64_t shape_index = 0) const;
  EpisodeOptions episode_options() const;
};

// "7 blocks (minimum 5), 6 cuts, return 23.41, complete, 1.2 ms"
std::string summary_line(const Decomposition& decomposition);

}  // namespace autoblock::cli
