// `autoblock`: decompose planar CAD faces into rectangular blocks from the command line.
//
// Exit status: 0 on success; 2 with one line "error: ..." on stderr for bad input or usage;
// 1 with one line "error: internal: ..." when something inside failed.
#include <Standard_Failure.hxx>

#include <CLI/CLI.hpp>

#include <iostream>

#include "cli/commands.h"
#include "core/common/error.h"

namespace {

// CLI11 messages can span lines; the contract is one line.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"AutoBlock: cut planar CAD faces into well-shaped rectangular blocks."};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("autoblock 0.1.0"));
  autoblock::cli::add_generate_command(app);
  autoblock::cli::add_decompose_command(app);
  autoblock::cli::add_eval_command(app);
  autoblock::cli::add_train_command(app);
  autoblock::cli::add_mesh_command(app);
  autoblock::cli::add_faces_command(app);
  autoblock::cli::add_combine_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << one_line(e.what()) << " (see autoblock --help)\n";
    return 2;
  } catch (const autoblock::InputError& e) {
    std::cerr << "error: " << one_line(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: internal: " << one_line(e.what()) << "\n";
    return 1;
  } catch (const Standard_Failure& e) {
    std::cerr << "error: internal: OpenCASCADE: " << one_line(e.GetMessageString()) << "\n";
    return 1;
  }
  return 0;
}
