// A real analysis of the CLI's hexahedral .inp with CalculiX (`ccx`, Debian calculix-ccx): the file
// `autoblock mesh SOLID --out bar.inp` writes, plus a small deck of our own (material, section,
// supports on the node sets, a load on a surface or node set by the names the file defines), checked
// against theory: a bar in tension (F L / (E A)) and a cantilever (F L^3 / (3 E I)).
#include <catch2/catch.hpp>

#include <BRepPrimAPI_MakePrism.hxx>

#include <cmath>
#include <sstream>

#include "core/geometry/occt_face.h"
#include "core/io/shape_file.h"
#include "core/io/text_file.h"
#include "support/mesh_readers.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

constexpr double kYoung = 210000.0, kPoisson = 0.3;

// The cross-section (any rectilinear face, holes allowed) extruded along +Z by length, meshed by the
// CLI into folder/bar.inp; returns the report.
nlohmann::json mesh_bar(const std::string& folder, const RectilinearPolygon& section, double length, double size,
                        const std::string& element) {
  const std::string solid = folder + "/bar.brep";
  write_shape_file(solid, BRepPrimAPI_MakePrism(occt_face_from_polygon(section, 0, true), gp_Vec(0, 0, length)).Shape());
  const auto r = test::run_autoblock("mesh '" + solid + "' --policy greedy --size " + std::to_string(size) + " --element " +
                                     element + " --out '" + folder + "/bar.inp' --json '" + folder + "/bar.json'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return test::read_json(folder + "/bar.json");
}

// The node number at (x, y, z) in the .inp's *NODE block (0 if none).
int node_at(const std::string& inp, double x, double y, double z) {
  std::istringstream in(inp);
  std::string line;
  bool nodes = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '*') {
      nodes = line.rfind("*NODE", 0) == 0;
      continue;
    }
    if (!nodes) continue;
    int id = 0;
    double p[3];
    char comma;
    std::istringstream items(line);
    items >> id >> comma >> p[0] >> comma >> p[1] >> comma >> p[2];
    if (std::fabs(p[0] - x) < 1e-9 && std::fabs(p[1] - y) < 1e-9 && std::fabs(p[2] - z) < 1e-9) return id;
  }
  return 0;
}

// Runs ccx on folder/job.inp (the mesh and the deck); returns the mean displacement component
// (0 x, 1 y, 2 z) over the nodes *NODE PRINT wrote, and their count.
std::pair<double, int> run_ccx(const std::string& folder, const std::string& deck, int component) {
  write_text_file(folder + "/job.inp", test::slurp_file(folder + "/bar.inp") + deck);
  const auto r = test::run_shell("cd '" + folder + "' && OMP_NUM_THREADS=1 ccx -i job");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("*ERROR") == std::string::npos);
  std::istringstream dat(test::slurp_file(folder + "/job.dat"));
  std::string line;
  double sum = 0.0;
  int count = 0;
  while (std::getline(dat, line)) {
    std::istringstream items(line);
    long id = 0;
    double u[3];
    if (items >> id >> u[0] >> u[1] >> u[2]) {
      sum += u[component];
      ++count;
    }
  }
  REQUIRE(count > 0);
  return {sum / count, count};
}

std::string material() {
  std::ostringstream s;
  s << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << kYoung << ", " << kPoisson << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n";
  return s.str();
}

}  // namespace

TEST_CASE("CalculiX on the CLI's .inp: a bar with a hole in tension stretches by F L / (E A)", "[cli][mesh][solid][calculix]") {
  const std::string folder = test::temporary_folder("ccx-bar");
  // An L-shaped section with a square hole: area 27 - 1 = 26.
  const RectilinearPolygon section =
      test::polygon_of({{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}});
  const double length = 20, area = 26, force = 1000;
  const nlohmann::json report = mesh_bar(folder, section, length, 1.0, "C3D8");
  const int bottom = report["caps"][0], top = report["caps"][1];
  const double sign = report["sweep"][2].get<double>() > 0 ? 1 : -1;
  const int fixed = sign > 0 ? bottom : top, loaded = sign > 0 ? top : bottom;
  const std::string inp = test::slurp_file(folder + "/bar.inp");
  const int a = node_at(inp, 0, 0, 0), b = node_at(inp, 6, 0, 0);
  REQUIRE(a > 0);
  REQUIRE(b > 0);
  // The fixed end slides freely in its plane (no rigid motion: a fixed in x and y, b in y), so the
  // stress is uniform and the answer exact for any mesh.
  std::ostringstream deck;
  deck << material() << "*BOUNDARY\nFACE_" << fixed << ", 3, 3, 0\n" << a << ", 1, 2, 0\n" << b << ", 2, 2, 0\n"
       << "*STEP\n*STATIC\n*DSLOAD\nSFACE_" << loaded << ", P, " << -force / area << "\n*NODE PRINT, NSET=FACE_" << loaded
       << "\nU\n*END STEP\n";
  const auto [stretch, nodes] = run_ccx(folder, deck.str(), 2);
  const double theory = force * length / (kYoung * area);
  INFO("stretch " << stretch << " over " << nodes << " nodes, theory " << theory);
  CHECK(std::fabs(stretch / theory - 1) < 0.005);
}

TEST_CASE("CalculiX on the CLI's .inp: a hollow cantilever's tip deflection (C3D8I) is F L^3 / (3 E I) within 5 %",
          "[cli][mesh][solid][calculix]") {
  const std::string folder = test::temporary_folder("ccx-cantilever");
  // A square tube 4 x 4 with a 2 x 2 hole, 40 long (length over depth 10): I = (4^4 - 2^4) / 12 = 20.
  const RectilinearPolygon section = test::polygon_of({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}});
  const double length = 40, inertia = 20, force = 100;
  const nlohmann::json report = mesh_bar(folder, section, length, 1.0, "C3D8I");
  const double sign = report["sweep"][2].get<double>() > 0 ? 1 : -1;
  const int fixed = sign > 0 ? report["caps"][0].get<int>() : report["caps"][1].get<int>();
  const int loaded = sign > 0 ? report["caps"][1].get<int>() : report["caps"][0].get<int>();
  // The tip's nodes share the force (24 of them: the 16 + 8 nodes of the tube's end at size 1).
  const int tip_nodes = 24;
  std::ostringstream deck;
  deck << material() << "*BOUNDARY\nFACE_" << fixed << ", 1, 3, 0\n*STEP\n*STATIC\n*CLOAD\nFACE_" << loaded << ", 2, "
       << force / tip_nodes << "\n*NODE PRINT, NSET=FACE_" << loaded << "\nU\n*END STEP\n";
  const auto [deflection, nodes] = run_ccx(folder, deck.str(), 1);
  REQUIRE(nodes == tip_nodes);
  const double theory = force * length * length * length / (3 * kYoung * inertia);
  INFO("tip deflection " << deflection << ", beam theory " << theory);
  CHECK(std::fabs(deflection / theory - 1) < 0.05);
}
