// Run the `autoblock` executable and capture what it says.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace autoblock::test {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

// Inputs: arguments, appended to the autoblock executable's path (shell syntax).
// Outputs: exit code, stdout and stderr.
CommandResult run_autoblock(const std::string& arguments);

// Inputs: command, a shell command line. Outputs: exit code, stdout and stderr.
CommandResult run_shell(const std::string& command);

// Inputs: path of a JSON file (a report the command wrote). Output: its parsed content.
nlohmann::json read_json(const std::string& path);

// Number of lines in text (a final line without newline counts).
int line_count(const std::string& text);

}  // namespace autoblock::test
