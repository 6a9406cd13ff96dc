// autoblock_bench_mesh: AutoBlock's mapped quad meshes (by default with the policies sac-mesh,
// greedy and optimal; --policy chooses) against Debian's
// gmsh 4.8 all-quad meshing on freshly generated faces. Gmsh runs Frontal-Delaunay for quads
// (Mesh.Algorithm 8, with Mesh.CrossFieldClosestPoint = 0: it crashes otherwise in 4.8) and the
// full-quad Blossom recombination (Mesh.RecombineAll = 1, Mesh.RecombinationAlgorithm = 3: no
// triangle left). Sizes: AutoBlock's default h (1/20 of the face's longer side); gmsh once with
// Mesh.MeshSizeMin = Mesh.MeshSizeMax = h, once with the size scaled per face so that its quad
// count comes close to the first AutoBlock policy's (two rounds of h' = h sqrt(gmsh's count /
// AutoBlock's)).
// Prints Markdown.
//
//   build/bin/autoblock_bench_mesh --small 200 --large 100
//   build/bin/autoblock_bench_mesh --arcs 200 --seed 20261202 --keep /tmp/arcbench
//
// --arcs N: N faces with circular arcs (arc_generator.h; the same faces as `autoblock generate --kind
// arcs --count N --seed S`), `autoblock mesh` as a whole process against gmsh, both judged by one
// check against the true face (curved_conformity.h: every boundary node on the face's lines and
// circles, the quads plus the gaps to the arcs covering the face); gmsh reads the same .brep file.
// --files F...: real faces instead, every planar face AutoBlock accepts in the files (each distinct
// one once, in its own frame at z = 0), meshed and judged as --arcs; the refused ones counted by
// reason (BENCHMARKS.md, "Real CAD faces").
//
// Quality is measured with the same code for both (mesh_quality.h); a gmsh mesh that comes out
// clockwise as a whole is reversed first (orientation is not quality; a single inverted quad
// stays inverted). Times: AutoBlock's is the whole run in
// the process (decomposition, cut replay and conformal merge in OpenCASCADE, interval assignment,
// meshing; no checks, no file I/O); gmsh's is its own "Done meshing 2D" wall time, and in another
// column the wall time of the whole gmsh process (start-up, reading the BREP, meshing, writing).
#include <CLI/CLI.hpp>
#include <BRepBuilderAPI_Transform.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Dir.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/baselines/baseline_policy.h"
#include "core/sac/compute_threads.h"
#include "core/api/policy_source.h"
#include "core/common/error.h"
#include "core/common/format.h"
#include "core/data/arc_generator.h"
#include "core/data/general_generator.h"
#include "core/data/shape_generator.h"
#include "core/env/decomposition.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/io/input_face.h"
#include "core/io/shape_file.h"
#include "core/io/text_file.h"
#include "core/mesh/block_model.h"
#include "core/mesh/mesh_conformity.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/mesh/mesh_quality.h"
#include "curved_conformity.h"
#include "gmsh_output.h"

using namespace autoblock;

namespace {

struct Sample {
  double min_sj = 0, mean_sj = 0, max_aspect = 0;
  double bound = 1.0;  // the face's scaled-Jacobian bound (general faces)
  int irregular = 0, quads = 0, triangles = 0;
  bool conformal = false;
  double seconds = 0, process_seconds = 0;
  // Faces with arcs: the judge against the true face (curved_conformity.h), and AutoBlock's own check.
  bench::CurvedConformity judged;
  bool own_conformal = false;
  double own_gap = 0.0;
  double off_relative = 0.0;  // the farthest boundary node from the face's boundary / the face's size
  double off_circles_relative = 0.0;  // the same over the nodes nearest a circle
  int blocks = 0;
};

struct Face {
  InputFace face;
  std::string brep;  // the face as a file, for gmsh
  // The loops the conformity check uses, and its tolerance (a general face: its lattice's).
  std::vector<Ring> loops;
  double tolerance = 0.0;
  // A face with arcs: judged against its true boundary (the model face), nodes within this distance.
  bool arcs = false;
  double judge_tolerance = 0.0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Sample autoblock_sample(const Face& f, const PolicySource& source) {
  const auto start = std::chrono::steady_clock::now();
  auto policy = source.make(f.face.grid.size, 0);
  const Decomposition d = decompose_face(f.face.grid, *policy);
  const MeshResult r = mesh_decomposition(f.face, d);
  Sample s;
  s.seconds = d.seconds + r.merge_seconds + r.interval_seconds + r.mesh_seconds;
  s.process_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.min_sj = r.quality.min_scaled_jacobian;
  s.mean_sj = r.quality.mean_scaled_jacobian;
  s.max_aspect = r.quality.max_aspect_ratio;
  s.irregular = r.quality.irregular_interior_nodes;
  s.quads = static_cast<int>(r.mesh.quads.size());
  s.conformal = r.conformity.conformal;
  return s;
}

// The surface elements of a gmsh .msh 4.1 ASCII file: quads into mesh, triangles counted.
QuadMesh read_gmsh_output(const std::string& path, int& triangles) {
  const bench::GmshOutput file = bench::read_gmsh_output_file(path);
  QuadMesh mesh;
  for (const auto& p : file.nodes) {
    mesh.nodes.push_back(Point2{p[0], p[1]});
    mesh.z = p[2];
  }
  triangles = file.elements.count(2) ? static_cast<int>(file.elements.at(2).size()) : 0;
  if (file.elements.count(3)) {
    for (const std::vector<int>& q : file.elements.at(3)) {
      mesh.quads.push_back({q[0], q[1], q[2], q[3]});
      mesh.quad_block.push_back(0);
    }
  }
  mesh.blocks = 1;
  // The face's orientation, not each quad's: a mesh that comes out clockwise is reversed as a
  // whole, so a quad inverted against its neighbours stays inverted.
  double twice = 0;
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    const auto c = mesh.corners(q);
    for (size_t k = 0; k < 4; ++k) twice += c[k].x * c[(k + 1) % 4].y - c[(k + 1) % 4].x * c[k].y;
  }
  if (twice < 0) {
    for (auto& q : mesh.quads) std::swap(q[1], q[3]);
  }
  return mesh;
}

Sample gmsh_sample(const Face& f, const std::string& folder, int k, double h) {
  const std::string geo = folder + "/face" + std::to_string(k) + ".geo", out = folder + "/face" + std::to_string(k) + ".msh";
  const std::string log = folder + "/gmsh.log";
  char settings[512];
  std::snprintf(settings, sizeof settings,
                "Mesh.Algorithm = 8;\nMesh.CrossFieldClosestPoint = 0;\nMesh.RecombineAll = 1;\n"
                "Mesh.RecombinationAlgorithm = 3;\n"
                "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeMin = %.17g;\nMesh.MeshSizeMax = %.17g;\n",
                h, h);
  write_text_file(geo, "SetFactory(\"OpenCASCADE\");\nMerge \"" + f.brep + "\";\n" + settings);
  const auto start = std::chrono::steady_clock::now();
  const std::string command = "gmsh '" + geo + "' -2 -format msh41 -o '" + out + "' > '" + log + "' 2>&1";
  const int status = std::system(command.c_str());
  Sample s;
  s.process_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    s.quads = -1;  // failed
    return s;
  }
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string said = text.str();
  if (std::regex_search(said, m, std::regex("Done meshing 2D \\(Wall ([0-9.eE+-]+)s"))) s.seconds = std::stod(m[1]);
  const QuadMesh mesh = read_gmsh_output(out, s.triangles);
  s.quads = static_cast<int>(mesh.quads.size());
  if (mesh.quads.empty()) return s;
  const MeshQuality q = mesh_quality(mesh);
  s.min_sj = q.min_scaled_jacobian;
  s.mean_sj = q.mean_scaled_jacobian;
  s.max_aspect = q.max_aspect_ratio;
  s.irregular = q.irregular_interior_nodes;
  if (f.arcs) {
    s.judged = bench::check_curved_conformity(mesh, f.face.model, f.judge_tolerance);
    s.off_relative = s.judged.worst_off / (1e6 * f.judge_tolerance);
    s.off_circles_relative = s.judged.worst_off_circles / (1e6 * f.judge_tolerance);
    s.conformal = s.triangles == 0 && s.judged.conformal;
    if (!s.judged.conformal) {
      std::fprintf(stderr, "gmsh mesh of face %d (size %.6g) is not conformal: %s (farthest boundary node %.3g off)\n", k, h,
                   s.judged.problem.c_str(), s.judged.worst_off);
    }
    return s;
  }
  const Conformity c = f.loops.empty() ? check_conformity(mesh, f.face.planar.polygon)
                                       : check_conformity(mesh, f.loops, f.tolerance);
  s.conformal = s.triangles == 0 && c.conformal;
  if (!c.conformal) std::fprintf(stderr, "gmsh mesh of face %d (size %.6g) is not conformal: %s\n", k, h, c.problem.c_str());
  return s;
}

// gmsh with its size scaled so that its quad count comes close to quads (AutoBlock's): two rescaling
// rounds from at_h, its run at size h (the count is not exactly proportional to 1 / size^2).
Sample gmsh_matched_sample(const Face& f, const std::string& folder, int k, double h, const Sample& at_h, int quads) {
  Sample matched = at_h;
  double size = h;
  for (int round = 0; round < 2 && matched.quads > 0 && quads > 0; ++round) {
    size *= std::sqrt(static_cast<double>(matched.quads) / quads);
    matched = gmsh_sample(f, folder, k, size);
  }
  return matched;
}

void print_row(const std::string& method, const std::vector<Sample>& samples) {
  std::vector<double> ms, process_ms;
  double worst_sj = 1e300, mean_min_sj = 0, mean_sj = 0, irregular = 0, quads = 0, aspect = 0;
  int with_irregular = 0, perfect = 0, conformal = 0, failed = 0;
  long triangles = 0;
  int n = 0;
  for (const Sample& s : samples) {
    if (s.quads < 0) {
      ++failed;
      continue;
    }
    ++n;
    ms.push_back(1e3 * s.seconds);
    process_ms.push_back(1e3 * s.process_seconds);
    worst_sj = std::min(worst_sj, s.min_sj);
    mean_min_sj += s.min_sj;
    mean_sj += s.mean_sj;
    irregular += s.irregular;
    with_irregular += s.irregular > 0;
    perfect += s.min_sj == 1.0 && s.irregular == 0;
    quads += s.quads;
    aspect += s.max_aspect;
    conformal += s.conformal;
    triangles += s.triangles;
  }
  double mean_ms = 0, mean_process = 0;
  for (double v : ms) mean_ms += v / std::max(1, n);
  for (double v : process_ms) mean_process += v / std::max(1, n);
  std::printf("| %s | %d/%zu | %.1f | %ld | %.4f | %.4f | %.4f | %.2f | %d | %.2f | %d | %d | %.2f | %.2f | %.1f |\n",
              method.c_str(), n, samples.size(), quads / std::max(1, n), triangles, worst_sj, mean_min_sj / std::max(1, n),
              mean_sj / std::max(1, n), irregular / std::max(1, n), with_irregular, aspect / std::max(1, n), perfect,
              conformal, mean_ms, median(ms), mean_process);
  if (failed) std::printf("<!-- %s failed on %d faces -->\n", method.c_str(), failed);
}

void run_set(const std::string& title, int count, int min_rects, int max_rects, std::uint64_t seed, bool holes,
             const std::vector<std::shared_ptr<PolicySource>>& policies, const std::string& folder) {
  std::mt19937_64 rng(seed);
  GeneratorOptions options;
  options.min_rects = min_rects;
  options.max_rects = max_rects;
  options.holes = holes;
  std::vector<Face> faces;
  for (int k = 0; k < count; ++k) {
    const GeneratedShape shape = generate_shape(rng, options);
    Face f;
    f.face = input_face_from_occt(occt_face_from_polygon(shape.polygon, 0, true), "generated");
    f.brep = folder + "/face" + std::to_string(k) + ".brep";
    write_shape_file(f.brep, f.face.occt);
    faces.push_back(std::move(f));
  }
  const std::string gmsh_h = "gmsh 4.8, size h", gmsh_matched = "gmsh 4.8, size matched to AutoBlock's count";
  std::map<std::string, std::vector<Sample>> samples;
  const bool tty = isatty(2);
  for (size_t k = 0; k < faces.size(); ++k) {
    Sample first;
    for (size_t p = 0; p < policies.size(); ++p) {
      const Sample sample = autoblock_sample(faces[k], *policies[p]);
      if (p == 0) first = sample;
      samples["AutoBlock " + policies[p]->name()].push_back(sample);
    }
    const double h = target_size_for(faces[k].face, 0.0);
    const Sample at_h = gmsh_sample(faces[k], folder, static_cast<int>(k), h);
    samples[gmsh_h].push_back(at_h);
    samples[gmsh_matched].push_back(gmsh_matched_sample(faces[k], folder, static_cast<int>(k), h, at_h, first.quads));
    if (tty) std::fprintf(stderr, "\r%s: %zu/%zu", title.c_str(), k + 1, faces.size());
  }
  if (tty) std::fprintf(stderr, "\n");
  std::printf("\n### %s (%d faces)\n\n", title.c_str(), count);
  std::printf("| method | meshed | mean quads | triangles left | worst min SJ | mean min SJ | mean SJ | mean irregular "
              "interior vertices | faces with irregular vertices | mean max aspect ratio | faces with min SJ 1 and no "
              "irregular vertex | conformal | mean ms | median ms | mean ms, whole process |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::vector<std::string> methods;
  for (const auto& p : policies) methods.push_back("AutoBlock " + p->name());
  methods.push_back(gmsh_h);
  methods.push_back(gmsh_matched);
  for (const std::string& method : methods) print_row(method, samples[method]);
}

// With --keep: the folder where every general face and its report are kept (for reading the worst).
std::string keep_folder, keep_tag;

// `autoblock mesh` on a general face, as a user runs it (the whole process), its figures from --json.
// A face with arcs also writes its mesh (.msh, as gmsh does), judged against the true face.
Sample cli_sample(const Face& f, const std::string& autoblock, const std::string& folder, int k) {
  const std::string json = folder + "/report" + std::to_string(k) + ".json";
  const std::string err = folder + "/error" + std::to_string(k) + ".txt";
  const std::string msh = folder + "/autoblock" + std::to_string(k) + ".msh";
  const std::string out = f.arcs ? " --out '" + msh + "'" : "";
  const std::string command = "'" + autoblock + "' mesh '" + f.brep + "' --json '" + json + "'" + out + " > /dev/null 2> '" + err + "'";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  Sample s;
  s.process_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    s.quads = -1;
    // Kept for whoever reads the table: the face and what autoblock said.
    const std::string kept = (std::filesystem::temp_directory_path() / "autoblock-bench-failures").string();
    std::filesystem::create_directories(kept);
    const std::string name = std::filesystem::path(f.brep).stem().string() + "-" + std::to_string(std::random_device{}());
    std::filesystem::copy_file(f.brep, kept + "/" + name + ".brep", std::filesystem::copy_options::overwrite_existing);
    std::ifstream said(err);
    std::stringstream text;
    text << said.rdbuf();
    std::printf("<!-- autoblock mesh failed on %s/%s.brep: %s -->\n", kept.c_str(), name.c_str(), text.str().c_str());
    if (!keep_folder.empty()) {
      const std::string named = keep_folder + "/" + keep_tag + "-face" + std::to_string(k);
      std::filesystem::copy_file(f.brep, named + ".brep", std::filesystem::copy_options::overwrite_existing);
      std::filesystem::copy_file(err, named + ".error.txt", std::filesystem::copy_options::overwrite_existing);
    }
    return s;
  }
  std::ifstream in(json);
  const nlohmann::json r = nlohmann::json::parse(in);
  if (!keep_folder.empty()) {
    const std::string name = keep_folder + "/" + keep_tag + "-face" + std::to_string(k);
    std::filesystem::copy_file(f.brep, name + ".brep", std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(json, name + ".json", std::filesystem::copy_options::overwrite_existing);
    if (f.arcs) std::filesystem::copy_file(msh, name + ".msh", std::filesystem::copy_options::overwrite_existing);
  }
  s.seconds = r["seconds"].get<double>();
  s.min_sj = r["quality"]["min_scaled_jacobian"].get<double>();
  s.mean_sj = r["quality"]["mean_scaled_jacobian"].get<double>();
  s.max_aspect = r["quality"]["max_aspect_ratio"].get<double>();
  s.irregular = r["quality"]["irregular_interior_vertices"].get<int>();
  s.quads = r["quads"].get<int>();
  s.conformal = r["conformal"].get<bool>();
  s.bound = r["quality"]["bound"].get<double>();
  s.blocks = r["blocks"].get<int>();
  if (f.arcs) {
    s.own_conformal = s.conformal;
    s.own_gap = r["conformity"]["curved_gap_area"].get<double>();
    int triangles = 0;
    s.judged = bench::check_curved_conformity(read_gmsh_output(msh, triangles), f.face.model, f.judge_tolerance);
    s.off_relative = s.judged.worst_off / (1e6 * f.judge_tolerance);
    s.off_circles_relative = s.judged.worst_off_circles / (1e6 * f.judge_tolerance);
    s.conformal = s.judged.conformal && triangles == 0;
  }
  return s;
}

const char* const kOurs = "AutoBlock `mesh` (default policy)";
const char* const kGmshH = "gmsh 4.8, size h";
const char* const kGmshMatched = "gmsh 4.8, size matched to AutoBlock's count";

// Every face meshed by `autoblock mesh` (cli_sample), by gmsh at size h and at AutoBlock's quad count;
// the samples by method (kOurs, kGmshH, kGmshMatched). With --keep, a face with arcs keeps gmsh's last mesh.
std::map<std::string, std::vector<Sample>> sample_faces(const std::string& title, const std::vector<Face>& faces,
                                                        const std::string& autoblock, const std::string& folder) {
  std::map<std::string, std::vector<Sample>> samples;
  const bool tty = isatty(2);
  for (size_t k = 0; k < faces.size(); ++k) {
    const int i = static_cast<int>(k);
    const Sample first = cli_sample(faces[k], autoblock, folder, i);
    samples[kOurs].push_back(first);
    const double h = target_size_for(faces[k].face, 0.0);
    Sample at_h = gmsh_sample(faces[k], folder, i, h);
    at_h.bound = first.bound;
    samples[kGmshH].push_back(at_h);
    samples[kGmshMatched].push_back(gmsh_matched_sample(faces[k], folder, i, h, at_h, first.quads));
    const std::string gmsh_mesh = folder + "/face" + std::to_string(k) + ".msh";
    if (faces[k].arcs && !keep_folder.empty() && std::filesystem::exists(gmsh_mesh)) {
      std::filesystem::copy_file(gmsh_mesh, keep_folder + "/" + keep_tag + "-face" + std::to_string(k) + "-gmsh.msh",
                                 std::filesystem::copy_options::overwrite_existing);
    }
    if (tty) std::fprintf(stderr, "\r%s: %zu/%zu", title.c_str(), k + 1, faces.size());
  }
  if (tty) std::fprintf(stderr, "\n");
  return samples;
}

// What the general and arc rows add up over a method's runs: each sample against its face's bound and
// gmsh's run at size h (the time reference).
struct RowTotals {
  std::vector<double> ms, process_ms, ratios, edge_ratios;
  double worst = 1e300, worst_sj = 1e300, mean_ratio = 0, mean_min_sj = 0, irregular = 0, quads = 0;
  int n = 0, conformal = 0, failed = 0;

  // Inputs: s; bound, its face's; gmsh, gmsh's run at size h. Output: false (counted as failed) when
  //         s has no mesh.
  bool add(const Sample& s, double bound, const Sample& gmsh) {
    if (s.quads <= 0) {
      ++failed;
      return false;
    }
    ++n;
    const double ratio = s.min_sj / bound;
    worst = std::min(worst, ratio);
    worst_sj = std::min(worst_sj, s.min_sj);
    mean_ratio += ratio;
    mean_min_sj += s.min_sj;
    irregular += s.irregular;
    quads += s.quads;
    conformal += s.conformal;
    edge_ratios.push_back(s.max_aspect);
    ms.push_back(1e3 * s.seconds);
    process_ms.push_back(1e3 * s.process_seconds);
    if (gmsh.quads > 0) ratios.push_back(s.process_seconds / gmsh.process_seconds);
    return true;
  }
  int divisor() const { return std::max(1, n); }
  // The faces' largest quad edge ratios (longest edge over shortest): their median, and "; N above 20"
  // where some face has a quad past that.
  std::string edge_ratio_column() const {
    int above = 0;
    for (const double r : edge_ratios) above += r > kEdgeRatioShown;
    char text[64];
    std::snprintf(text, sizeof text, "%.1f; %d", median(edge_ratios), above);
    return text;
  }
  static constexpr double kEdgeRatioShown = 20.0;
};

// Inputs: method; samples, its runs; bounds, AutoBlock's runs (their faces' bounds); gmsh, gmsh's runs at
// size h (the time reference).
void print_general_row(const std::string& method, const std::vector<Sample>& samples, const std::vector<Sample>& bounds,
                       const std::vector<Sample>& gmsh) {
  RowTotals t;
  int above = 0;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (t.add(samples[k], bounds[k].bound, gmsh[k])) above += samples[k].min_sj / bounds[k].bound >= 0.8;
  }
  const int d = t.divisor();
  std::printf("| %s | %d/%zu | %.1f | %.4f | %.4f | %d | %.4f | %.2f | %s | %d | %.1f | %.1f | %.2f |\n", method.c_str(), t.n,
              samples.size(), t.quads / d, t.worst, t.mean_ratio / d, above, t.mean_min_sj / d, t.irregular / d,
              t.edge_ratio_column().c_str(), t.conformal, median(t.ms), median(t.process_ms), median(t.ratios));
  if (t.failed) std::printf("<!-- %s failed on %d faces -->\n", method.c_str(), t.failed);
}

// General faces: AutoBlock's `mesh` (default policy) and gmsh, side by side.
void run_general_set(const std::string& title, const std::vector<GeneralOptions>& kinds, int count, std::uint64_t seed,
                     const std::string& autoblock, const std::string& folder) {
  std::mt19937_64 rng(seed);
  keep_tag = "seed" + std::to_string(seed);
  if (!keep_folder.empty()) std::filesystem::create_directories(keep_folder);
  std::vector<Face> faces;
  for (int k = 0; k < count; ++k) {
    const GeneralShape shape = generate_general_shape(rng, kinds[static_cast<size_t>(k) % kinds.size()]);
    Face f;
    f.face = input_face_from_occt(occt_face_from_polygon(RectilinearPolygon{shape.outer, shape.holes}, 0, true), "generated");
    f.brep = folder + "/face" + std::to_string(k) + ".brep";
    write_shape_file(f.brep, f.face.model);
    if (f.face.is_general()) {
      f.loops = f.face.region.loops();
      f.tolerance = kModelToleranceQuanta * f.face.region.quantum();
    }
    faces.push_back(std::move(f));
  }
  const std::string ours = kOurs, gmsh_h = kGmshH, gmsh_matched = kGmshMatched;
  std::map<std::string, std::vector<Sample>> samples = sample_faces(title, faces, autoblock, folder);
  std::printf("\n### %s (%d faces)\n\n", title.c_str(), count);
  std::printf("| method | meshed | mean quads | worst min SJ / bound | mean min SJ / bound | faces >= 0.8 of the bound | "
              "mean min SJ | mean irregular interior vertices | largest quad edge ratio: median; faces above 20 | conformal | "
              "median ms in process | median ms, whole process | median whole-process time / gmsh's at size h |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  // Every row divides by the face's bound (AutoBlock's report gives it) and by gmsh's time at size h.
  for (const std::string& method : {ours, gmsh_h, gmsh_matched}) {
    print_general_row(method, samples[method], samples[ours], samples[gmsh_h]);
  }
}

// Faces with arcs: one row per method. Inputs: samples, its runs; ours, AutoBlock's (the bound and the
// SJ compared against); gmsh_h, gmsh's at size h (the time reference).
void print_arc_row(const std::string& method, const std::vector<Sample>& samples, const std::vector<Sample>& ours,
                   const std::vector<Sample>& gmsh_h, bool is_ours) {
  RowTotals t;
  double worst_off = 0, worst_off_circles = 0;
  int own = 0, off_faces = 0, above = 0;
  for (size_t k = 0; k < samples.size(); ++k) {
    const Sample& s = samples[k];
    if (!t.add(s, ours[k].bound, gmsh_h[k])) continue;
    own += s.own_conformal && s.own_gap != 0.0;
    off_faces += s.judged.nodes_off > 0;
    worst_off = std::max(worst_off, s.off_relative);
    worst_off_circles = std::max(worst_off_circles, s.off_circles_relative);
    // AutoBlock's minimum at least this method's on the face (both meshed; AutoBlock failing counts as below).
    if (!is_ours) above += ours[k].quads > 0 && ours[k].min_sj >= s.min_sj;
  }
  const int d = t.divisor();
  const std::string own_column = is_ours ? std::to_string(own) : "-";
  const std::string above_column = is_ours ? "-" : std::to_string(above) + "/" + std::to_string(samples.size());
  std::printf("| %s | %d/%zu | %d | %s | %d (%.1e; on circles %.1e) | %.1f | %.4f | %.4f | %.4f | %.4f | %s | %.2f | %s | %.1f | %.2f |\n", method.c_str(),
              t.n, samples.size(), t.conformal, own_column.c_str(), off_faces, worst_off, worst_off_circles, t.quads / d, t.mean_min_sj / d,
              t.mean_ratio / d, t.worst_sj, t.worst, above_column.c_str(), t.irregular / d, t.edge_ratio_column().c_str(),
              median(t.process_ms), median(t.ratios));
  if (t.failed) std::printf("<!-- %s failed on %d faces -->\n", method.c_str(), t.failed);
}

// Faces with arcs, and real faces: one row per method (print_arc_row).
void print_arc_table(std::map<std::string, std::vector<Sample>>& samples) {
  const std::string ours = kOurs, gmsh_h = kGmshH, gmsh_matched = kGmshMatched;
  std::printf("| method | meshed | conformal (true face) | conformal (own check, gap != 0) | faces with a boundary node off "
              "the boundary (farthest / face size; of the nodes nearest a circle) | mean quads | mean min SJ | mean min SJ / bound | worst min SJ | worst min SJ / bound | faces "
              "where AutoBlock's min SJ >= this | mean irregular interior vertices | largest quad edge ratio: median; faces "
              "above 20 | median ms, whole process | median whole-process time / gmsh's at size h |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& method : {ours, gmsh_h, gmsh_matched}) {
    print_arc_row(method, samples[method], samples[ours], samples[gmsh_h], method == ours);
  }
}

// Per kind of face: AutoBlock's and gmsh's (matched) mean min SJ / bound, the faces where AutoBlock's
// minimum is at least gmsh's (both sizes), the irregular vertices, and the faces AutoBlock failed on.
// Inputs: kind_of, each face's kind; samples, by method (sample_faces).
void print_kind_rows(const std::vector<std::string>& kind_of, std::map<std::string, std::vector<Sample>>& samples) {
  std::map<std::string, int> kinds;
  for (const std::string& k : kind_of) ++kinds[k];
  std::printf("\n| kind | faces | AutoBlock mean min SJ / bound | gmsh (matched) mean min SJ / bound | AutoBlock >= gmsh "
              "(h and matched) | AutoBlock mean irregular | gmsh (matched) mean irregular | AutoBlock failed |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& [kind, n] : kinds) {
    double ab = 0, gm = 0, abi = 0, gmi = 0;
    int m = 0, above = 0, failed = 0;
    for (size_t k = 0; k < kind_of.size(); ++k) {
      const Sample &a = samples[kOurs][k], &g = samples[kGmshMatched][k], &gh = samples[kGmshH][k];
      if (kind_of[k] != kind) continue;
      if (a.quads <= 0) {
        ++failed;
        continue;
      }
      ++m;
      ab += a.min_sj / a.bound;
      gm += g.min_sj / a.bound;
      abi += a.irregular;
      gmi += g.irregular;
      above += a.min_sj >= g.min_sj && a.min_sj >= gh.min_sj;
    }
    const int d = std::max(1, m);
    std::printf("| %s | %d | %.4f | %.4f | %d/%d | %.2f | %.2f | %d |\n", kind.c_str(), n, ab / d, gm / d, above, m, abi / d, gmi / d, failed);
  }
}

// The ten worst faces by AutoBlock's min SJ / bound, and every face where it is below gmsh's or not
// conformal. Inputs: label and kind, each face's (for the first two columns); samples, by method.
void print_worst_faces(const std::vector<std::string>& label, const std::vector<std::string>& kind,
                       std::map<std::string, std::vector<Sample>>& samples) {
  std::vector<size_t> order(label.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  auto score = [&](size_t k) { return samples[kOurs][k].quads > 0 ? samples[kOurs][k].min_sj / samples[kOurs][k].bound : -1.0; };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return score(a) < score(b); });
  std::printf("\nWorst faces (AutoBlock's min SJ / bound), and every face where it is below gmsh's or not conformal:\n\n");
  std::printf("| face | kind | AutoBlock blocks, quads | min SJ | bound | gmsh min SJ (h, matched) | irregular (AutoBlock, gmsh matched) | "
              "AutoBlock conformal | problem |\n|---|---|---:|---:|---:|---:|---:|---|---|\n");
  for (size_t i = 0; i < order.size(); ++i) {
    const size_t k = order[i];
    const Sample &a = samples[kOurs][k], &g = samples[kGmshMatched][k], &gh = samples[kGmshH][k];
    const bool below = a.quads > 0 && (a.min_sj < g.min_sj || a.min_sj < gh.min_sj);
    if (i >= 10 && !below && a.conformal && a.quads > 0) continue;
    std::printf("| %s | %s | %d, %d | %.4f | %.4f | %.4f, %.4f | %d, %d | %s | %s |\n", label[k].c_str(), kind[k].c_str(), a.blocks,
                a.quads, a.min_sj, a.bound, gh.min_sj, g.min_sj, a.irregular, g.irregular,
                a.quads <= 0 ? "failed" : a.conformal ? "yes" : "no", a.judged.problem.c_str());
  }
}

// Faces with circular arcs (issue 13's benchmark): AutoBlock's `mesh` against gmsh, judged alike.
void run_arc_set(int count, std::uint64_t seed, const std::string& autoblock, const std::string& folder) {
  std::mt19937_64 rng(seed);
  keep_tag = "arcs-seed" + std::to_string(seed);
  if (!keep_folder.empty()) std::filesystem::create_directories(keep_folder);
  std::vector<Face> faces;
  std::vector<ArcFace> made;
  for (int k = 0; k < count; ++k) {
    made.push_back(generate_arc_face(rng, ArcOptions{}));
    Face f;
    f.face = input_face_from_occt(made.back().face, made.back().name);
    f.brep = folder + "/face" + std::to_string(k) + ".brep";
    write_shape_file(f.brep, f.face.model);
    f.arcs = true;
    f.judge_tolerance = 1e-6 * f.face.region.bbox().longer_side();
    faces.push_back(std::move(f));
  }
  const std::string ours = kOurs, gmsh_h = kGmshH, gmsh_matched = kGmshMatched;
  std::map<std::string, std::vector<Sample>> samples = sample_faces("faces with arcs", faces, autoblock, folder);
  int with_holes = 0;
  std::map<std::string, int> kinds;
  for (const ArcFace& f : made) {
    with_holes += f.holes > 0;
    ++kinds[arc_kind_name(f.kind)];
  }
  std::printf("\n### Faces with circular arcs, seed %llu (%d faces, %d with holes:", static_cast<unsigned long long>(seed), count,
              with_holes);
  for (const auto& [kind, n] : kinds) std::printf(" %s %d", kind.c_str(), n);
  std::printf(")\n\n");
  print_arc_table(samples);
  // Per kind, and the faces to look at.
  std::vector<std::string> kind_of, label, kind_column;
  for (size_t k = 0; k < made.size(); ++k) {
    kind_of.push_back(arc_kind_name(made[k].kind));
    label.push_back(keep_tag + "-face" + std::to_string(k));
    kind_column.push_back(kind_of.back() + " (" + made[k].name + ")");
  }
  print_kind_rows(kind_of, samples);
  print_worst_faces(label, kind_column, samples);
}

// Real CAD faces: every planar face of the files that AutoBlock accepts, each distinct one once (a
// part's repeated faces, the same outline at the same size, counted once), written in its own frame
// and meshed like the faces with arcs: `autoblock mesh` against gmsh, judged against the true face.
// The faces AutoBlock refuses are counted by reason.
void run_file_set(const std::vector<std::string>& files, const std::string& autoblock, const std::string& folder) {
  keep_tag = "real";
  if (!keep_folder.empty()) std::filesystem::create_directories(keep_folder);
  std::vector<Face> faces;
  std::vector<std::string> names, kinds;
  std::map<std::string, int> refused;
  std::set<std::string> seen;
  int planar = 0, repeated = 0;
  for (const std::string& path : files) {
    const TopoDS_Shape shape = read_shape_file(path);
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, TopAbs_FACE, map);
    for (int i = 1; i <= map.Extent(); ++i) {
      const TopoDS_Face occt = TopoDS::Face(map(i));
      gp_Dir normal;
      if (!planar_face_normal(occt, &normal)) continue;
      ++planar;
      const std::string name = std::filesystem::path(path).filename().string() + " Face" + std::to_string(i);
      Face f;
      try {
        f.face = input_face_from_occt(occt, name);
      } catch (const InputError& e) {
        std::string why = e.what();
        why = why.substr(why.find(": ") + 2);
        // The reason without its numbers.
        std::string kind;
        for (char c : why) {
          if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-') {
            if (kind.empty() || kind.back() != '#') kind += '#';
          } else {
            kind += c;
          }
        }
        ++refused[kind];
        continue;
      }
      // The same outline at the same size: its area, perimeter and vertex count, to 6 digits.
      const double area = occt_area(f.face.occt);
      const Box box = f.face.is_general() ? f.face.region.bbox() : ring_bbox(f.face.planar.polygon.outer);
      size_t vertices = f.face.planar.polygon.outer.size();
      for (const Ring& hole : f.face.planar.polygon.holes) vertices += hole.size();
      if (f.face.is_general()) vertices = static_cast<size_t>(f.face.region.vertex_count());
      char key[160];
      std::snprintf(key, sizeof key, "%.6g %.6g %.6g %zu %zu", area, box.longer_side(), box.shorter_side(), vertices,
                    f.face.arcs.arcs.size());
      if (!seen.insert(key).second) {
        ++repeated;
        continue;
      }
      const size_t holes = f.face.is_general() ? f.face.region.holes().size() : f.face.planar.polygon.holes.size();
      std::string kind = !f.face.arcs.arcs.empty() ? "with arcs" : !f.face.is_general() ? (vertices == 4 && holes == 0 ? "rectangle" : "rectilinear") : "polygon";
      if (holes > 0) kind += ", holes";
      f.brep = folder + "/face" + std::to_string(faces.size()) + ".brep";
      // In its frame, moved to z = 0 (where the judge, curved_conformity.h, puts the meshes' nodes).
      gp_Trsf down;
      down.SetTranslation(gp_Vec(0, 0, -f.face.planar.z));
      write_shape_file(f.brep, BRepBuilderAPI_Transform(f.face.occt, down, true).Shape());
      // The face as written is the one meshed and judged.
      f.face = load_input_face(f.brep);
      f.face.source = name;
      f.arcs = true;
      f.judge_tolerance = 1e-6 * box.longer_side();
      faces.push_back(std::move(f));
      names.push_back(name);
      kinds.push_back(kind);
    }
  }
  const std::string ours = kOurs, gmsh_h = kGmshH, gmsh_matched = kGmshMatched;
  std::map<std::string, std::vector<Sample>> samples = sample_faces("real faces", faces, autoblock, folder);
  std::printf("\n### Real CAD faces: %s, %s, %zu distinct accepted (%s left out)\n\n",
              counted(static_cast<long long>(files.size()), "file").c_str(), counted(planar, "planar face").c_str(), faces.size(),
              counted(repeated, "repeat").c_str());
  std::printf("Refused (the reason without its numbers):%s\n\n", refused.empty() ? " none" : "");
  for (const auto& [why, n] : refused) std::printf("- %d: %s\n", n, why.c_str());
  std::printf("\n");
  print_arc_table(samples);
  std::vector<std::string> label;
  for (size_t k = 0; k < faces.size(); ++k) label.push_back(names[k] + " (real-face" + std::to_string(k) + ")");
  print_kind_rows(kinds, samples);
  print_worst_faces(label, kinds, samples);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"AutoBlock's mapped quad meshes against gmsh's all-quad meshes on generated faces."};
  int small = 200, large = 100, chamfered_count = -1;
  std::uint64_t seed = 404;
  bool holes = false;
  double time_limit = 30.0;
  std::vector<std::string> policy_names{"sac-mesh", "greedy", "optimal"};
  app.add_option("--policy", policy_names, "AutoBlock policies to compare (the first sets gmsh's matched count)")
      ->capture_default_str();
  app.add_option("--small", small, "faces of 2-10 rectangles")->capture_default_str();
  app.add_option("--large", large, "faces of 11-40 rectangles")->capture_default_str();
  app.add_option("--seed", seed, "generator seed (the large set uses seed + 1)")->capture_default_str();
  app.add_flag("--holes", holes, "faces with one or two holes");
  app.add_option("--time-limit", time_limit, "optimal: search seconds per face")->capture_default_str();
  bool general = false;
  app.add_flag("--general", general,
               "general faces instead (edges at any angle): --small polygons of 5-12 vertices, --large of 13-40, a "
               "quarter with holes, and --chamfered chamfered unions of rectangles; AutoBlock runs as `autoblock mesh`");
  app.add_option("--keep", keep_folder, "with --general or --arcs: keep every face (.brep) and AutoBlock's report (.json) in this folder (--arcs: also both meshes, .msh; a face autoblock fails on: .brep and .error.txt)");
  int arcs = 0;
  app.add_option("--arcs", arcs,
                 "faces with circular arcs instead: this many (filleted unions, plates with holes, slotted plates, rounded "
                 "polygons, rounded plates with holes; the faces of `autoblock generate --kind arcs --seed S`); AutoBlock "
                 "runs as `autoblock mesh`");
  std::vector<std::string> files;
  app.add_option("--files", files,
                 "real faces instead: every planar face AutoBlock accepts in these .brep/.step files, each distinct one once "
                 "(in its own frame); AutoBlock runs as `autoblock mesh`; the refused ones are counted by reason");
  app.add_option("--chamfered", chamfered_count, "with --general: chamfered unions of 2-6 rectangles (default: as many as --small)");
  CLI11_PARSE(app, argc, argv);
  try {
    const std::string folder =
        (std::filesystem::temp_directory_path() / ("autoblock-bench-mesh-" + std::to_string(std::random_device{}()))).string();
    std::filesystem::create_directories(folder);
    set_compute_threads(1);
    if (!files.empty()) {
      run_file_set(files, (std::filesystem::path(argv[0]).parent_path() / "autoblock").string(), folder);
      std::filesystem::remove_all(folder);
      return 0;
    }
    if (arcs > 0) {
      run_arc_set(arcs, seed, (std::filesystem::path(argv[0]).parent_path() / "autoblock").string(), folder);
      std::filesystem::remove_all(folder);
      return 0;
    }
    if (general) {
      const std::string autoblock = (std::filesystem::path(argv[0]).parent_path() / "autoblock").string();
      auto polygons = [](int lo, int hi) {
        std::vector<GeneralOptions> kinds;
        for (int k = 0; k < 4; ++k) {
          GeneralOptions o;
          o.min_vertices = lo;
          o.max_vertices = hi;
          o.holes = k == 3;
          kinds.push_back(o);
        }
        return kinds;
      };
      GeneralOptions chamfered;
      chamfered.kind = GeneralKind::Chamfered;
      GeneralOptions chamfered_holes = chamfered;
      chamfered_holes.holes = true;
      if (small > 0) run_general_set("polygons of 5-12 vertices, a quarter with holes, seed " + std::to_string(seed), polygons(5, 12), small, seed, autoblock, folder);
      if (large > 0) run_general_set("polygons of 13-40 vertices, a quarter with holes, seed " + std::to_string(seed + 1), polygons(13, 40), large, seed + 1, autoblock, folder);
      if (chamfered_count < 0) chamfered_count = small;
      if (chamfered_count > 0) run_general_set("chamfered unions of 2-6 rectangles, a quarter with holes, seed " + std::to_string(seed + 2),
                                     {chamfered, chamfered, chamfered, chamfered_holes}, chamfered_count, seed + 2, autoblock, folder);
      std::filesystem::remove_all(folder);
      return 0;
    }
    std::vector<std::shared_ptr<PolicySource>> policies;
    for (const std::string& name : policy_names) {
      BaselineOptions options;
      options.optimal_seconds = time_limit;
      policies.push_back(std::make_shared<PolicySource>(name, options));
    }
    const std::string kind = holes ? ", with holes" : "";
    if (small > 0) run_set("2-10 rectangles" + kind + ", seed " + std::to_string(seed), small, 2, 10, seed, holes, policies, folder);
    if (large > 0) {
      run_set("11-40 rectangles" + kind + ", seed " + std::to_string(seed + 1), large, 11, 40, seed + 1, holes, policies, folder);
    }
    std::filesystem::remove_all(folder);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
