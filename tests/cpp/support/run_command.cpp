#include "support/run_command.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/test_shapes.h"

namespace autoblock::test {

namespace {
std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

CommandResult run_shell(const std::string& command) {
  const std::string folder = temporary_folder("run");
  const std::string out = folder + "/out.txt", err = folder + "/err.txt";
  const std::string line = command + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(line.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(out);
  result.err = slurp(err);
  return result;
}

CommandResult run_autoblock(const std::string& arguments) {
  return run_shell(std::string("'") + AUTOBLOCK_CLI + "' " + arguments);
}

int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  if (!text.empty() && text.back() != '\n') ++lines;
  return lines;
}

}  // namespace autoblock::test
