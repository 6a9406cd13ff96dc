// autoblock decompose FILE [--face N] [--policy NAME] [--out blocks.brep] [--json report.json]
//                          [--picture blocks.svg] [--seed S] [--max-steps N] [--time-limit T]
// A swept solid (FILE holds one solid, no --face): its cap is decomposed, --out writes the prisms.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "core/api/face_actions.h"
#include "core/api/solid_meshing.h"
#include "core/common/error.h"
#include "core/common/format.h"
#include "core/io/decomposition_json.h"
#include "core/io/shape_file.h"
#include "core/io/svg_picture.h"
#include "core/io/text_file.h"
#include "core/raster/picture_file.h"

namespace autoblock::cli {
namespace {

struct Arguments {
  std::string file, out, json, picture;
  PolicyArguments policy;
  FaceArguments face;
};

std::string general_summary(const RegionDecomposition& d) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s%s, %s, return %.3f, %s%s, %.1f ms", counted(d.blocks, "block").c_str(),
                d.templates ? (" + " + counted(d.templates, "template")).c_str() : "",
                counted(static_cast<long long>(d.cuts.size()), "step").c_str(), d.total_return, status_name(d.status).c_str(),
                d.time_capped ? " (time limit hit: progress cuts finished)" : "", d.seconds * 1000.0);
  return buf;
}

// Every face through core/api: the grid engine for a rectilinear face, the general one otherwise.
void decompose(const Arguments& args) {
  const MeshInput input = load_mesh_input(args.file, args.face.face, args.face.how_to_choose(args.file));
  const InputFace& face = input.is_solid ? input.solid.cap : input.face;
  DecomposeSettings settings = args.policy.decompose_settings();
  // The blocks as OpenCASCADE cuts them from the input face (checked against the engine at every
  // cut), merged into one conformal model: neighbours share edges and vertices.
  settings.occt_blocks = !args.out.empty();
  const FaceDecomposition made = decompose_input_face(face, settings);
  const std::string name = std::filesystem::path(args.file).filename().string();
  std::string policy, summary, report, picture;
  if (made.general()) {
    const RegionDecomposition& d = made.region;
    policy = d.policy + " (general engine)";
    summary = general_summary(d);
    if (!args.json.empty()) report = region_decomposition_json(args.file, face, d).dump(2) + "\n";
    if (!args.picture.empty()) picture = region_decomposition_svg(face.region, d, name + " - policy " + d.policy + " | " + summary);
  } else {
    const Decomposition& d = made.decomposition;
    policy = d.policy;
    summary = summary_line(d);
    if (!args.json.empty()) {
      nlohmann::json json = decomposition_json(args.file, face.planar, d);
      json["engine"] = "grid";
      json["frame"] = frame_json(face.frame);
      report = json.dump(2) + "\n";
    }
    if (!args.picture.empty()) {
      picture = decomposition_svg(face.planar.polygon, d.blocks, d.cuts, name + " - policy " + d.policy + " | " + summary);
    }
  }
  std::string source = face.source;
  if (input.is_solid) {
    const SweptSolid& solid = input.solid;
    source = solid.source + ": solid, caps Face" + std::to_string(solid.bottom) + " and Face" + std::to_string(solid.top) +
             " (the blocks of Face" + std::to_string(solid.bottom) + " swept)";
    if (!report.empty()) {
      nlohmann::json json = nlohmann::json::parse(report);
      json["solid"] = {{"caps", {solid.bottom, solid.top}},
                       {"sweep", {solid.sweep.X(), solid.sweep.Y(), solid.sweep.Z()}},
                       {"volume", solid.volume}};
      report = json.dump(2) + "\n";
    }
  }
  // Everything is made before anything is written.
  const TopoDS_Shape blocks = args.out.empty() ? TopoDS_Shape() : input.is_solid ? TopoDS_Shape(swept_blocks(input.solid, made).compound) : made.shape;
  if (!args.out.empty()) write_shape_file(args.out, blocks);
  if (!args.json.empty()) write_text_file(args.json, report);
  if (!args.picture.empty()) write_picture(args.picture, picture);
  std::cout << source << ": " << policy << ": " << summary << "\n";
  if (!args.out.empty()) std::cout << "  blocks:  " << args.out << "\n";
  if (!args.json.empty()) std::cout << "  report:  " << args.json << "\n";
  if (!args.picture.empty()) std::cout << "  picture: " << args.picture << "\n";
}

}  // namespace

void add_decompose_command(CLI::App& app) {
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("decompose", "Cut one planar face into blocks (rectangles on faces with edges along two perpendicular directions, quadrilaterals otherwise).");
  command->add_option("FILE", args->file, "a .brep, .step or .stp file: one planar face, a part with --face N, or a swept solid")->required();
  args->face.add_to(*command);
  args->policy.add_to(*command);
  command->add_option("--out", args->out, "write the blocks (a conformal compound of faces sharing their edges; a swept solid's: "
                                          "prisms sharing their faces) to a .brep, .step or .stp file");
  command->add_option("--json", args->json, "write the report as JSON");
  command->add_option("--picture", args->picture, "write a picture of the blocks (.svg or .png)");
  command->callback([args] {
    require_extension(args->out, {".brep", ".brp", ".step", ".stp"}, "--out");
    if (!args->picture.empty()) check_picture_path(args->picture, "--picture");
    decompose(*args);
  });
}

}  // namespace autoblock::cli
