// The `autoblock` subcommands: each adds itself to the application and runs from its callback.
#pragma once

#include <CLI/CLI.hpp>

namespace autoblock::cli {

void add_generate_command(CLI::App& app);
void add_decompose_command(CLI::App& app);
void add_eval_command(CLI::App& app);
void add_train_command(CLI::App& app);
void add_mesh_command(CLI::App& app);
void add_faces_command(CLI::App& app);
void add_combine_command(CLI::App& app);

}  // namespace autoblock::cli
