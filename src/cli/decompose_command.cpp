// autoblock decompose FILE [--face N] [--policy NAME] [--out blocks.brep] [--json report.json]
//                          [--picture blocks.svg] [--seed S] [--max-steps N] [--time-limit T]
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "core/common/error.h"
#include "core/env/occt_replay.h"
#include "core/mesh/conformal_merge.h"
#include "core/io/decomposition_json.h"
#include "core/io/shape_file.h"
#include "core/io/svg_picture.h"
#include "core/io/text_file.h"
#include "core/raster/picture_file.h"

namespace autoblock::cli {
namespace {

void require_extension(const std::string& path, const std::vector<std::string>& allowed, const std::string& option) {
  if (path.empty()) return;
  const std::string ext = std::filesystem::path(path).extension().string();
  for (const std::string& a : allowed) {
    if (ext == a) return;
  }
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw InputError(option + " " + path + ": expected a " + list + " file");
}

}  // namespace

void add_decompose_command(CLI::App& app) {
  struct Arguments {
    std::string file, out, json, picture;
    PolicyArguments policy;
    FaceArguments face;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("decompose", "Cut one planar face into rectangular blocks.");
  command->add_option("FILE", args->file, "a .brep, .step or .stp file: one planar face, or a part with --face N")->required();
  args->face.add_to(*command);
  args->policy.add_to(*command);
  command->add_option("--out", args->out, "write the blocks (a conformal compound of faces sharing their edges) to a .brep, .step or .stp file");
  command->add_option("--json", args->json, "write the report as JSON");
  command->add_option("--picture", args->picture, "write a picture of the blocks (.svg or .png)");
  command->callback([args] {
    require_extension(args->out, {".brep", ".brp", ".step", ".stp"}, "--out");
    if (!args->picture.empty()) check_picture_path(args->picture, "--picture");
    const InputFace face = args->face.load(args->file);
    std::unique_ptr<Policy> policy = args->policy.make(face);
    const EpisodeOptions options = args->policy.episode_options();
    const Decomposition result = decompose_face(face.grid, *policy, options);
    if (!args->out.empty()) {
      // The blocks as OpenCASCADE cuts them from the input face (checked against the grid engine at
      // every cut), then merged into one conformal model: neighbours share edges and vertices.
      const ConformalBlocks model = conformal_merge(replay_cuts_occt(face.occt, face.grid, result.cuts, options));
      write_shape_file(args->out, model.compound);
    }
    if (!args->json.empty()) {
      write_text_file(args->json, decomposition_json(args->file, face.planar, result).dump(2) + "\n");
    }
    if (!args->picture.empty()) {
      const std::string title = std::filesystem::path(args->file).filename().string() + " - policy " + result.policy +
                                " | " + summary_line(result);
      write_picture(args->picture, decomposition_svg(face.planar.polygon, result.blocks, result.cuts, title));
    }
    std::cout << face.source << ": " << result.policy << ": " << summary_line(result) << "\n";
    if (!args->out.empty()) std::cout << "  blocks:  " << args->out << "\n";
    if (!args->json.empty()) std::cout << "  report:  " << args->json << "\n";
    if (!args->picture.empty()) std::cout << "  picture: " << args->picture << "\n";
  });
}

}  // namespace autoblock::cli
