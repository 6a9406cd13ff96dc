// Benchmark (issue 11): AutoBlock's hexahedral meshes of swept solids against gmsh 4.8 sweeping its
// own recombined quad mesh, on freshly generated extrusions.
//
//   build/bin/autoblock_bench_hex --count 200 --general 50 --seed 2026
//   build/bin/autoblock_bench_hex --count 0 --general 0 --arcs 200 --seed 2026
//
// Solids: the faces of the project's generators (unions of 2-40 rectangles, a quarter with holes;
// general polygons of 5-12 vertices, a quarter with holes), extruded by 0.2-0.8 of the face's longer
// side, every other one obliquely (10-30 degrees from the normal, any direction). AutoBlock runs as a
// user runs it: `autoblock mesh SOLID.brep --json` (default policy, size and layers), one process per
// solid. gmsh gets the bottom cap with the same size h (Frontal-Delaunay for quads, Blossom, as in
// bench_mesh) and sweeps it with AutoBlock's layer count: `Extrude {sweep} { Surface{1}; Layers{N};
// Recombine; }`, and again with its size scaled to match AutoBlock's hexahedron count. Quality
// (Verdict's hex scaled Jacobian, irregular edges) and the conformity check (faces shared by two hexahedra, volume and surface area
// the solid's, no inverted hexahedron) are the same code for both (hex_quality.h, hex_conformity.h);
// a gmsh mesh with prisms (triangles left in its quad mesh) is not all-hex. Times are whole-process
// wall times, paired per solid; the last column is the median of the per-solid ratios. With --keep DIR
// the solids (solidK.brep), their caps (capK.brep) and AutoBlock's reports (reportK.json) stay in DIR,
// K numbering the solids as generated: two runs' reports pair per solid.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Vec.hxx>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/data/arc_generator.h"
#include "core/data/general_generator.h"
#include "core/data/shape_generator.h"
#include "core/geometry/occt_face.h"
#include "core/io/shape_file.h"
#include "core/io/text_file.h"
#include "core/mesh/hex_conformity.h"
#include "core/mesh/hex_quality.h"
#include "bench_stats.h"
#include "gmsh_output.h"

using namespace autoblock;

namespace {

struct Solid {
  std::string brep, cap_brep;  // the solid, and its bottom cap alone (for gmsh)
  gp_Vec sweep;
  bool oblique = false;
  double volume = 0.0, area = 0.0;
};

struct Sample {
  bool ok = false;
  int hexes = 0, prisms = 0, layers = 0;
  double min_sj = 0, mean_sj = 0, irregular = 0, size = 0;
  bool conformal = false;
  double process_seconds = 0;
};

Solid make_solid(const TopoDS_Face& cap, std::mt19937_64& rng, bool oblique, const std::string& folder, int k) {
  Bnd_Box box;
  BRepBndLib::Add(cap, box);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double size = std::max(x1 - x0, y1 - y0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double length = size * (0.2 + 0.6 * unit(rng));
  gp_Vec sweep(0, 0, length);
  if (oblique) {
    const double tilt = (10.0 + 20.0 * unit(rng)) * M_PI / 180.0, turn = 2.0 * M_PI * unit(rng);
    sweep = gp_Vec(length * std::tan(tilt) * std::cos(turn), length * std::tan(tilt) * std::sin(turn), length);
  }
  Solid s;
  s.sweep = sweep;
  s.oblique = oblique;
  const TopoDS_Shape prism = BRepPrimAPI_MakePrism(cap, sweep).Shape();
  GProp_GProps volume, area;
  BRepGProp::VolumeProperties(prism, volume);
  BRepGProp::SurfaceProperties(prism, area);
  s.volume = volume.Mass();
  s.area = area.Mass();
  s.brep = folder + "/solid" + std::to_string(k) + ".brep";
  s.cap_brep = folder + "/cap" + std::to_string(k) + ".brep";
  write_shape_file(s.brep, prism);
  write_shape_file(s.cap_brep, cap);
  return s;
}

Sample autoblock_sample(const Solid& s, const std::string& autoblock, const std::string& folder, int k) {
  const std::string json = folder + "/report" + std::to_string(k) + ".json";
  const std::string err = folder + "/error" + std::to_string(k) + ".txt";
  const std::string command = "'" + autoblock + "' mesh '" + s.brep + "' --json '" + json + "' > /dev/null 2> '" + err + "'";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  Sample r;
  r.process_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    std::ifstream said(err);
    const std::string text((std::istreambuf_iterator<char>(said)), std::istreambuf_iterator<char>());
    std::printf("<!-- autoblock mesh failed on solid %d (%s): %s -->\n", k, s.brep.c_str(), text.c_str());
    return r;
  }
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  r.ok = true;
  r.hexes = j["hexahedra"].get<int>();
  r.layers = j["layers"].get<int>();
  r.size = j["target_size"].get<double>();
  r.min_sj = j["quality"]["min_scaled_jacobian"].get<double>();
  r.mean_sj = j["quality"]["mean_scaled_jacobian"].get<double>();
  r.irregular = j["quality"]["irregular_edges"].get<double>();
  r.conformal = j["conformal"].get<bool>();
  return r;
}

// The volume elements of a gmsh .msh 4.1 ASCII file: hexahedra into mesh, other volumes counted.
HexMesh read_gmsh_volumes(const std::string& path, int& others) {
  const bench::GmshOutput file = bench::read_gmsh_output_file(path);
  HexMesh mesh;
  mesh.nodes = file.nodes;
  others = 0;
  for (const auto& [type, list] : file.elements) {
    if (type == 5) {
      for (const std::vector<int>& h : list) {
        mesh.hexes.push_back({h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]});
        mesh.hex_block.push_back(0);
      }
    } else if (type == 4 || type == 6 || type == 7) {
      others += static_cast<int>(list.size());
    }
  }
  mesh.blocks = 1;
  return mesh;
}

Sample gmsh_sample(const Solid& s, double size, int layers, const std::string& folder, int k) {
  const std::string geo = folder + "/solid" + std::to_string(k) + ".geo", out = folder + "/solid" + std::to_string(k) + ".msh";
  const std::string log = folder + "/gmsh.log";
  char settings[1024];
  std::snprintf(settings, sizeof settings,
                "Mesh.Algorithm = 8;\nMesh.CrossFieldClosestPoint = 0;\nMesh.RecombineAll = 1;\n"
                "Mesh.RecombinationAlgorithm = 3;\n"
                "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeMin = %.17g;\nMesh.MeshSizeMax = %.17g;\n"
                "Extrude {%.17g, %.17g, %.17g} { Surface{1}; Layers{%d}; Recombine; }\n",
                size, size, s.sweep.X(), s.sweep.Y(), s.sweep.Z(), std::max(1, layers));
  write_text_file(geo, "SetFactory(\"OpenCASCADE\");\nMerge \"" + s.cap_brep + "\";\n" + settings);
  const auto start = std::chrono::steady_clock::now();
  const std::string command = "gmsh '" + geo + "' -3 -format msh41 -o '" + out + "' > '" + log + "' 2>&1";
  const int status = std::system(command.c_str());
  Sample r;
  r.process_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) return r;
  HexMesh mesh = read_gmsh_volumes(out, r.prisms);
  std::filesystem::remove(out);
  r.hexes = static_cast<int>(mesh.hexes.size());
  if (mesh.hexes.empty()) return r;
  r.ok = true;
  const HexMeshQuality q = hex_mesh_quality(mesh);
  r.min_sj = q.min_scaled_jacobian;
  r.mean_sj = q.mean_scaled_jacobian;
  r.irregular = q.irregular_edges;
  // The conformity check on the mesh alone: its faces used once are its boundary, all on "face 1"
  // whose area is the solid's surface (gmsh's faces carry no tags of ours).
  std::map<std::array<int, 4>, std::pair<int, BoundaryQuad>> uses;
  for (size_t h = 0; h < mesh.hexes.size(); ++h) {
    for (int side = 0; side < 6; ++side) {
      std::array<int, 4> key = hex_face_nodes(mesh.hexes[h], side);
      std::sort(key.begin(), key.end());
      auto& u = uses[key];
      ++u.first;
      u.second = {static_cast<int>(h), side, 1};
    }
  }
  for (const auto& [key, u] : uses) {
    if (u.first == 1) mesh.boundary.push_back(u.second);
  }
  r.size = size;
  r.layers = layers;
  SolidFigures figures;
  figures.volume = s.volume;
  figures.area = s.area;
  figures.face_areas = {s.area};
  const HexConformity c = check_hex_conformity(mesh, figures);
  r.conformal = r.prisms == 0 && c.conformal;
  if (!c.conformal) std::fprintf(stderr, "gmsh mesh of solid %d is not conformal: %s\n", k, c.problem.c_str());
  return r;
}

void print_row(const std::string& method, const std::vector<Sample>& samples, const std::vector<Sample>& gmsh) {
  int n = 0, conformal = 0, perfect = 0;
  double hexes = 0, worst = 1e300, mean_min = 0, mean_mean = 0, irregular = 0;
  std::vector<double> ms, ratios;
  for (size_t k = 0; k < samples.size(); ++k) {
    const Sample& s = samples[k];
    if (!s.ok) continue;
    ++n;
    hexes += s.hexes;
    worst = std::min(worst, s.min_sj);
    mean_min += s.min_sj;
    mean_mean += s.mean_sj;
    irregular += s.irregular;
    conformal += s.conformal ? 1 : 0;
    perfect += s.min_sj >= 1.0 - 1e-9 ? 1 : 0;
    ms.push_back(1e3 * s.process_seconds);
    if (gmsh[k].process_seconds > 0) ratios.push_back(s.process_seconds / gmsh[k].process_seconds);
  }
  const double d = std::max(1, n);
  std::printf("| %s | %d/%zu | %.0f | %.4f | %.4f | %.4f | %d | %.2f | %d | %.1f | %.2f |\n", method.c_str(), n,
              samples.size(), hexes / d, n ? worst : 0.0, mean_min / d, mean_mean / d, perfect, irregular / d, conformal,
              bench::quantile(ms, 0.5), bench::quantile(ratios, 0.5));
}

// gmsh with its cap's size scaled so that its hexahedron count (same layers) comes close to
// AutoBlock's: two rounds of h' = h sqrt(gmsh's count / AutoBlock's).
Sample gmsh_matched_sample(const Solid& s, const Sample& ours, const Sample& at_h, const std::string& folder, int k) {
  Sample matched = at_h;
  for (int round = 0; round < 2 && matched.ok && matched.hexes > 0; ++round) {
    const double size = matched.size * std::sqrt(static_cast<double>(matched.hexes) / std::max(1, ours.hexes));
    matched = gmsh_sample(s, size, ours.layers, folder, k);
  }
  return matched;
}

void run_set(const std::string& title, const std::vector<Solid>& solids, const std::string& autoblock,
             const std::string& folder, int first) {
  std::vector<Sample> ours, gmsh, matched;
  const bool tty = isatty(2);
  for (size_t k = 0; k < solids.size(); ++k) {
    const int id = first + static_cast<int>(k);
    ours.push_back(autoblock_sample(solids[k], autoblock, folder, id));
    gmsh.push_back(ours.back().ok ? gmsh_sample(solids[k], ours.back().size, ours.back().layers, folder, id) : Sample{});
    matched.push_back(ours.back().ok ? gmsh_matched_sample(solids[k], ours.back(), gmsh.back(), folder, id) : Sample{});
    if (tty) std::fprintf(stderr, "\r%s: %zu/%zu", title.c_str(), k + 1, solids.size());
  }
  if (tty) std::fprintf(stderr, "\n");
  std::printf("\n### %s (%zu solids)\n\n", title.c_str(), solids.size());
  std::printf("| method | meshed all-hex | mean hexahedra | worst min SJ | mean min SJ | mean mean SJ | solids with min SJ 1 | "
              "mean irregular edges | conformal, volume exact | median ms, whole process | median time / gmsh's |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  print_row("AutoBlock `mesh` (defaults)", ours, gmsh);
  for (auto [label, samples] : {std::pair<const char*, std::vector<Sample>>{"same h and layers", gmsh},
                                 {"layers the same, size matched to AutoBlock's count", matched}}) {
    int with_prisms = 0;
    for (Sample& s : samples) {
      with_prisms += s.prisms > 0 ? 1 : 0;
      s.ok = s.ok && s.prisms == 0;
    }
    print_row(std::string("gmsh 4.8, Extrude with Layers and Recombine, ") + label, samples, gmsh);
    if (with_prisms) std::printf("<!-- gmsh left prisms (triangles in its quad mesh) in %d solids -->\n", with_prisms);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"AutoBlock's hexahedral meshes of swept solids against gmsh's swept meshes."};
  int count = 200, general = 50, arcs = 0;
  std::uint64_t seed = 2026;
  app.add_option("--count", count, "extrusions of rectangle unions (2-40 rectangles, a quarter with holes)")->capture_default_str();
  app.add_option("--general", general, "extrusions of general polygons (5-12 vertices, a quarter with holes)")->capture_default_str();
  app.add_option("--arcs", arcs, "extrusions of faces with circular arcs (`autoblock generate --kind arcs`: fillets, "
                 "round holes, slots; normal sweeps, their sides cylinders)")->capture_default_str();
  app.add_option("--seed", seed, "generator seed")->capture_default_str();
  std::string keep;
  app.add_option("--keep", keep, "keep every solid (solidK.brep), its cap (capK.brep) and AutoBlock's report (reportK.json) "
                 "in this folder (default: a temporary folder)");
  CLI11_PARSE(app, argc, argv);
  const std::string autoblock = (std::filesystem::path(argv[0]).parent_path() / "autoblock").string();
  const std::string folder =
      keep.empty() ? (std::filesystem::temp_directory_path() / ("autoblock-bench-hex-" + std::to_string(::getpid()))).string() : keep;
  std::filesystem::create_directories(folder);
  std::mt19937_64 rng(seed);
  std::vector<Solid> rectilinear, polygons;
  for (int k = 0; k < count; ++k) {
    GeneratorOptions options;
    options.min_rects = 2;
    options.max_rects = k % 2 == 0 ? 10 : 40;
    options.holes = k % 4 == 3;
    const GeneratedShape shape = generate_shape(rng, options);
    rectilinear.push_back(make_solid(occt_face_from_polygon(shape.polygon, 0, true), rng, (k / 2) % 2 == 1, folder, k));
  }
  for (int k = 0; k < general; ++k) {
    GeneralOptions options;
    options.min_vertices = 5;
    options.max_vertices = 12;
    options.holes = k % 4 == 3;
    const GeneralShape shape = generate_general_shape(rng, options);
    const TopoDS_Face cap = occt_face_from_polygon(RectilinearPolygon{shape.outer, shape.holes}, 0, true);
    polygons.push_back(make_solid(cap, rng, (k / 2) % 2 == 1, folder, count + k));
  }
  std::vector<Solid> rounded;
  for (int k = 0; k < arcs; ++k) {
    const ArcFace face = generate_arc_face(rng, ArcOptions{});
    rounded.push_back(make_solid(face.face, rng, false, folder, count + general + k));
  }
  std::printf("# Swept solids: AutoBlock against gmsh 4.8 (seed %llu)\n", static_cast<unsigned long long>(seed));
  if (count > 0) run_set("extrusions of 2-40 rectangle unions, a quarter with holes, half oblique", rectilinear, autoblock, folder, 0);
  if (general > 0) run_set("extrusions of polygons of 5-12 vertices, a quarter with holes, half oblique", polygons, autoblock, folder, count);
  if (arcs > 0) {
    // (gmsh's chords miss the cylinders' segments, so its conformity check, against the solid's true
    // volume and area, fails by that; AutoBlock's counts the segments, hex_conformity.h.)
    run_set("extrusions of faces with circular arcs (fillets, round holes, slots), normal", rounded, autoblock, folder,
            count + general);
  }
  return 0;
}
