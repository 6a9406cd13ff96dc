// Pieces shared by the commands: policy options and summaries.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/env/decomposition.h"
#include "core/env/episode.h"
#include "core/io/input_face.h"
#include "core/api/catalog.h"
#include "core/api/face_actions.h"
#include "core/api/policy_source.h"

namespace autoblock::cli {

// The options every command that runs a policy takes.
struct PolicyArguments {
  std::string policy;  // empty: the shipped default
  std::uint64_t seed = 0;
  int max_steps = 0;
  double time_limit = 30.0;
  std::string reward;  // empty: the policy's own preset (paper for baselines)

  void add_to(CLI::App& command);
  // Loads the policy (once). Throws InputError.
  std::shared_ptr<const PolicySource> source() const;
  // Inputs: face; shape_index, added to the seed so that each shape of a set has its own stream.
  std::unique_ptr<Policy> make(const InputFace& face, std::uint64_t shape_index = 0) const;
  EpisodeOptions episode_options() const;
  // The policy settings of core/api (api/catalog.h): seed (plus shape_index), time limits, reward.
  // --time-limit sets both engines' budgets when given; else each keeps its own default.
  PolicySettings policy_settings(std::uint64_t shape_index = 0) const;
  // What core/api's decompose_input_face takes from these options (OpenCASCADE blocks off).
  DecomposeSettings decompose_settings(std::uint64_t shape_index = 0) const;

 private:
  mutable std::shared_ptr<const PolicySource> source_;
  CLI::Option* time_limit_option_ = nullptr;
};

// The --face option of the commands that read a face from a file.
struct FaceArguments {
  int face = 0;  // 1-based, as FreeCAD numbers faces (Face1, Face2, ...); 0: the file's only face

  void add_to(CLI::App& command);
  // Inputs: file. Output: its chosen face, checked. Throws InputError that says how to choose.
  InputFace load(const std::string& file) const;
  // Inputs: file. Output: what the messages say when the file holds several faces and none was chosen.
  std::string how_to_choose(const std::string& file) const;
};

// Inputs: path (empty: nothing to check); allowed extensions (".brep", ...); option, for the message.
// Throws InputError when path has none of them.
void require_extension(const std::string& path, const std::vector<std::string>& allowed, const std::string& option);

// "7 blocks (minimum 5), 6 cuts, return 23.41, complete, 1.2 ms"
std::string summary_line(const Decomposition& decomposition);

}  // namespace autoblock::cli
