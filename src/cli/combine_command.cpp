// autoblock combine --grid POLICY --general POLICY --out FILE: one policy file with two value
// networks, the first for faces whose edges run along two perpendicular directions, the second for
// every other face (issue 12: a network trained on general faces ships beside the grid network).
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/api/policy_source.h"

namespace autoblock::cli {

namespace {

// What a network was trained on, from its meta's "training" (empty when the file does not say).
std::string trained_on(const nlohmann::json& training) {
  if (!training.is_object() || !training.contains("train")) return "";
  const nlohmann::json& train = training.at("train");
  std::string text = train.is_string() ? train.get<std::string>() : train.dump();
  if (training.contains("episodes")) text += ", " + std::to_string(training.value("episodes", 0)) + " episodes";
  return " (trained on " + text + ")";
}

}  // namespace

void add_combine_command(CLI::App& app) {
  struct Args {
    std::string grid, general, out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "combine", "Write one policy file with two value networks: one for faces whose edges run along two perpendicular "
                 "directions, one for every other face (edges at other angles, arcs).");
  command->add_option("--grid", args->grid, "policy (shipped name or file) whose network decides on rectilinear faces")
      ->required();
  command->add_option("--general", args->general,
                      "policy (shipped name or file) whose network decides on general faces")
      ->required();
  command->add_option("--out", args->out, "the policy file to write")->required();
  command->callback([args] {
    const nlohmann::json meta = nlohmann::json::parse(combine_policies(args->grid, args->general, args->out));
    std::cout << args->out << ": rectilinear faces by " << args->grid << "'s network"
              << trained_on(meta.value("training", nlohmann::json::object())) << ", general faces by "
              << args->general << "'s" << trained_on(meta.at("general").value("training", nlohmann::json::object()))
              << "\n";
  });
}

}  // namespace autoblock::cli
