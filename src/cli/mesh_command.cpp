// autoblock mesh FILE [--face N] [--policy NAME] [--size H] [--intervals X0,Y0,X1,Y1=N ...]
//                     [--smoothing N] [--out mesh.msh|.vtu|.inp] [--picture mesh.svg|.png] [--json report.json]
//                     [--seed S] [--max-steps N] [--time-limit T]
//                     a swept solid (FILE holds one solid, no --face): [--layers N] [--grading R]
//                     [--element C3D8|C3D8I] [--blocks blocks.brep|.step]
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "core/common/error.h"
#include "core/common/format.h"
#include "core/io/text_file.h"
#include "core/api/face_meshing.h"
#include "core/api/solid_meshing.h"
#include "core/io/shape_file.h"
#include "core/mesh/hex_export.h"
#include "core/mesh/mesh_export.h"
#include "core/raster/picture_file.h"

namespace autoblock::cli {
namespace {

// "X0,Y0,X1,Y1=N" -> EdgeIntervals.
EdgeIntervals parse_edge_intervals(const std::string& text) {
  const std::string usage = "--intervals " + text + ": expected X0,Y0,X1,Y1=N (a stretch and its interval count)";
  const size_t eq = text.find('=');
  if (eq == std::string::npos) throw InputError(usage);
  std::vector<double> v;
  std::stringstream coordinates(text.substr(0, eq));
  std::string item;
  while (std::getline(coordinates, item, ',')) {
    size_t used = 0;
    try {
      v.push_back(std::stod(item, &used));
    } catch (const std::exception&) {
      throw InputError(usage);
    }
    if (used != item.size()) throw InputError(usage);
  }
  size_t used = 0;
  long n = 0;
  try {
    n = std::stol(text.substr(eq + 1), &used);
  } catch (const std::exception&) {
    throw InputError(usage);
  }
  if (v.size() != 4 || used != text.size() - eq - 1 || n < 1 || n > 100000000) throw InputError(usage);
  return EdgeIntervals{Point2{v[0], v[1]}, Point2{v[2], v[3]}, static_cast<int>(n)};
}

void require_folder(const std::string& path, const std::string& option) {
  if (path.empty()) return;
  const std::filesystem::path p(path);
  std::error_code ec;
  if (p.has_parent_path() && !std::filesystem::is_directory(p.parent_path(), ec)) {
    throw InputError(option + " " + path + ": the folder " + p.parent_path().string() + " does not exist");
  }
}

// The element size to four significant digits, as a plain decimal.
std::string size_text(const MeshResult& r) { return format_significant(r.intervals.target_size, 4); }

// "0.9613 (0.97 of the bound 0.9239)" for a general face, "0.9613" for a rectilinear one.
std::string jacobian_text(const FaceMeshing& m) {
  char buf[128];
  const MeshResult& r = m.result;
  if (m.general()) {
    std::snprintf(buf, sizeof buf, "%.4g (%.3g of the bound %.4g)", r.quality.min_scaled_jacobian,
                  r.quality.min_scaled_jacobian / r.bound, r.bound);
  } else {
    std::snprintf(buf, sizeof buf, "%.4g", r.quality.min_scaled_jacobian);
  }
  return buf;
}

std::string mesh_summary(const FaceMeshing& m) {
  const MeshResult& r = m.result;
  char buf[640];
  std::snprintf(buf, sizeof buf, "%s, %s, %s, size %s (max deviation %.1f %%), min scaled Jacobian %s, %s, %s, %.1f ms",
                counted(static_cast<long long>(m.blocks()), "block").c_str(),
                counted(static_cast<long long>(r.mesh.nodes.size()), "node").c_str(),
                counted(static_cast<long long>(r.mesh.quads.size()), "quad").c_str(), size_text(r).c_str(),
                100.0 * r.intervals.max_relative_deviation, jacobian_text(m).c_str(),
                counted(r.quality.irregular_interior_nodes, "irregular interior vertex", "irregular interior vertices").c_str(),
                r.conformity.conformal ? "conformal" : "NOT conformal", m.seconds * 1000.0);
  return buf;
}

// The picture's second title line, short enough for its width.
std::string picture_summary(const FaceMeshing& m) {
  const MeshResult& r = m.result;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s, %s, size %s, min scaled Jacobian %.4g, %s",
                counted(static_cast<long long>(m.blocks()), "block").c_str(),
                counted(static_cast<long long>(r.mesh.quads.size()), "quad").c_str(), size_text(r).c_str(),
                r.quality.min_scaled_jacobian,
                counted(r.quality.irregular_interior_nodes, "irregular vertex", "irregular vertices").c_str());
  return buf;
}

std::string solid_summary(const SolidMeshing& m) {
  const HexMeshQuality& q = m.quality;
  char buf[640];
  std::snprintf(buf, sizeof buf, "%s, %s, %s, %s, size %s, min scaled Jacobian %.4g, %s, %s, %.1f ms",
                counted(static_cast<long long>(m.blocks()), "block").c_str(),
                counted(static_cast<long long>(m.mesh.nodes.size()), "node").c_str(),
                counted(static_cast<long long>(m.mesh.hexes.size()), "hexahedron", "hexahedra").c_str(),
                counted(m.mesh.layers, "layer").c_str(), format_significant(m.target_size, 4).c_str(),
                q.min_scaled_jacobian, counted(q.irregular_edges, "irregular edge").c_str(),
                m.conformity.conformal ? "conformal" : "NOT conformal", m.seconds * 1000.0);
  return buf;
}

struct Arguments {
  std::string file, out, json, picture;
  double size = 0.0;
  int smoothing = kDefaultSmoothingSweeps;
  std::vector<std::string> intervals;
  PolicyArguments policy;
  FaceArguments face;
  int layers = 0;
  double grading = 1.0;
  std::string element = "C3D8", blocks;
};

// A swept solid: its cap meshed with options, swept; everything made before anything is written.
void mesh_solid(const Arguments& args, const SweptSolid& solid, const MeshOptions& options) {
  SolidMeshOptions solid_options;
  solid_options.cap = options;
  solid_options.layers = args.layers;
  solid_options.grading = args.grading;
  const SolidMeshing meshing = mesh_swept_solid(solid, args.policy.decompose_settings(), solid_options);
  const std::string report = args.json.empty() ? "" : solid_meshing_json(args.file, meshing).dump(2) + "\n";
  if (!meshing.conformity.conformal) {
    if (!args.json.empty()) write_text_file(args.json, report);
    require_conformal(meshing);
  }
  const std::string mesh_text = args.out.empty() ? "" : mesh_file_text(args.out, meshing.mesh, args.element);
  const std::string title = std::filesystem::path(args.file).filename().string() + " - policy " + meshing.cap.policy() +
                            " | " + counted(static_cast<long long>(meshing.blocks()), "block") + ", " +
                            counted(static_cast<long long>(meshing.mesh.hexes.size()), "hexahedron", "hexahedra") +
                            ", min scaled Jacobian " + format_significant(meshing.quality.min_scaled_jacobian, 4);
  const std::string picture = args.picture.empty() ? "" : solid_meshing_svg(meshing, title);
  const PrismBlocks prisms = args.blocks.empty() ? PrismBlocks{} : solid_meshing_blocks(meshing);
  if (!args.out.empty()) write_text_file(args.out, mesh_text);
  if (!args.picture.empty()) write_picture(args.picture, picture);
  if (!args.blocks.empty()) write_shape_file(args.blocks, prisms.compound);
  if (!args.json.empty()) write_text_file(args.json, report);
  std::cout << solid.source << ": solid, caps Face" << solid.bottom << " and Face" << solid.top << ": "
            << meshing.cap.policy() << ": " << solid_summary(meshing) << "\n";
  if (!args.out.empty()) std::cout << "  mesh:    " << args.out << "\n";
  if (!args.blocks.empty()) std::cout << "  blocks:  " << args.blocks << "\n";
  if (!args.json.empty()) std::cout << "  report:  " << args.json << "\n";
  if (!args.picture.empty()) std::cout << "  picture: " << args.picture << "\n";
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("mesh", "Decompose one planar face into blocks and mesh them with quadrilaterals; or a swept solid with hexahedra.");
  command->add_option("FILE", args->file, "a .brep, .step or .stp file: one planar face, a part with --face N, or a swept solid (hexahedra)")->required();
  args->face.add_to(*command);
  args->policy.add_to(*command);
  command->add_option("--size", args->size,
                      "target element size (default: 1/20 of the longer side of the face's bounding box; a solid's: of the "
                      "longest side of its bounding box)")
      ->check(CLI::PositiveNumber);
  command->add_option("--intervals", args->intervals,
                      "X0,Y0,X1,Y1=N: the stretch from (X0,Y0) to (X1,Y1) gets exactly N intervals (repeatable)");
  command->add_option("--smoothing", args->smoothing,
                      "a general face's mesh: sweeps of smoothing that never moves boundary nodes nor lowers the "
                      "minimum scaled Jacobian (0: none)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command->add_option("--out", args->out, "write the mesh: .msh (Gmsh 4.1), .vtu (VTK) or .inp (Abaqus/CalculiX)");
  command->add_option("--picture", args->picture, "write a picture of the blocks and the mesh (.svg or .png)");
  command->add_option("--json", args->json, "write the report as JSON");
  CLI::Option* layers = command->add_option("--layers", args->layers,
                      "a solid: the number of layers along the sweep (default: the sweep's length over the element size; at least one between splits of its sides)")
      ->check(CLI::Range(1, 1000000));
  CLI::Option* grading = command->add_option("--grading", args->grading,
                      "a solid: each layer's thickness over the previous one's (default 1: uniform)")
      ->check(CLI::PositiveNumber);
  CLI::Option* element = command->add_option("--element", args->element,
                      "a solid's .inp: C3D8 (default) or C3D8I (incompatible modes, for bending)")
      ->check(CLI::IsMember({"C3D8", "C3D8I"}));
  CLI::Option* blocks = command->add_option("--blocks", args->blocks,
                      "a solid: write its hexahedral blocks (prisms sharing their faces) to a .brep, .step or .stp file");
  command->callback([args, layers, grading, element, blocks] {
    if (!args->out.empty() && !is_mesh_file_name(args->out)) {
      throw InputError("--out " + args->out + ": expected a .msh, .vtu or .inp file");
    }
    if (!args->picture.empty()) check_picture_path(args->picture, "--picture");
    require_folder(args->out, "--out");
    require_folder(args->picture, "--picture");
    require_folder(args->json, "--json");
    require_folder(args->blocks, "--blocks");
    if (!args->blocks.empty()) require_extension(args->blocks, {".brep", ".brp", ".step", ".stp"}, "--blocks");
    MeshOptions options;
    options.size = args->size;
    options.smoothing_sweeps = args->smoothing;
    for (const std::string& text : args->intervals) options.fixed.push_back(parse_edge_intervals(text));

    const MeshInput input = load_mesh_input(args->file, args->face.face, args->face.how_to_choose(args->file));
    if (input.is_solid) {
      mesh_solid(*args, input.solid, options);
      return;
    }
    for (const CLI::Option* o : {layers, grading, element, blocks}) {
      if (o->count() > 0) throw InputError(o->get_name() + " is for solids; " + args->file + " gives a face");
    }
    const InputFace& face = input.face;
    options.occt_model = false;  // a face's mesh and its report need no OpenCASCADE model of the blocks
    const FaceMeshing meshing = mesh_input_face(face, args->policy.decompose_settings(), options);
    const MeshResult& result = meshing.result;

    // Everything is made before anything is written.
    const std::string report = args->json.empty() ? "" : face_meshing_json(args->file, meshing).dump(2) + "\n";
    if (!result.conformity.conformal) {
      if (!args->json.empty()) write_text_file(args->json, report);
      require_conformal(result);
    }
    const std::string mesh_text = args->out.empty() ? "" : mesh_file_text(args->out, result.mesh, face.frame);
    const std::string title = std::filesystem::path(args->file).filename().string() + " - policy " + meshing.policy() +
                              " | " + picture_summary(meshing);
    const std::string picture = args->picture.empty() ? "" : face_meshing_svg(meshing, title);
    if (!args->out.empty()) write_text_file(args->out, mesh_text);
    if (!args->picture.empty()) write_picture(args->picture, picture);
    if (!args->json.empty()) write_text_file(args->json, report);
    if (meshing.general() && !meshing.decomposition.region.fallback_from.empty()) {
      const RegionDecomposition& d = meshing.decomposition.region;
      std::cout << face.source << ": the blocks of " << d.fallback_from << " could not be meshed (" << d.fallback_reason
                << "); meshed the search's blocks instead\n";
    }
    std::cout << face.source << ": " << meshing.policy() << ": " << mesh_summary(meshing) << "\n";
    if (!args->out.empty()) std::cout << "  mesh:    " << args->out << "\n";
    if (!args->json.empty()) std::cout << "  report:  " << args->json << "\n";
    if (!args->picture.empty()) std::cout << "  picture: " << args->picture << "\n";
  });
}

}  // namespace autoblock::cli
