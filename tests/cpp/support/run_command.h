// Run the `autoblock` executable and capture what it says.
#pragma once

#include <string>

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

// Number of lines in text (a final line without newline counts).
int line_count(const std::string& text);

}  // namespace autoblock::test
