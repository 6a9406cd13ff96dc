#include <catch2/catch.hpp>

#include <cmath>

#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/geometry/occt_face.h"
#include "core/io/face_selection.h"
#include "core/io/input_face.h"
#include "core/io/shape_file.h"
#include "support/bad_shapes.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {

// The part written to a STEP file, as a user would have it.
std::string part_step_file() {
  const std::string path = test::temporary_folder("face-selection") + "/part.step";
  write_shape_file(path, test::part_with_many_faces());
  return path;
}

std::vector<int> usable_faces(const std::vector<FaceSummary>& faces) {
  std::vector<int> numbers;
  for (const FaceSummary& f : faces) {
    if (f.problem.empty()) numbers.push_back(f.number);
  }
  return numbers;
}

}  // namespace

TEST_CASE("list_faces numbers a STEP part's faces as FreeCAD does and says which AutoBlock takes",
          "[io][faces]") {
  const std::string path = part_step_file();
  const TopoDS_Shape shape = read_shape_file(path);
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_FACE, map);
  const std::vector<FaceSummary> faces = list_faces(shape);
  REQUIRE(faces.size() == 15);  // the slab: 6 + 4 sides, top, bottom; the cylinder: side, top, bottom
  REQUIRE(map.Extent() == 15);
  int planes = 0, cylinders = 0;
  for (size_t k = 0; k < faces.size(); ++k) {
    const FaceSummary& f = faces[k];
    CHECK(f.number == static_cast<int>(k) + 1);
    CHECK(f.surface == surface_name(TopoDS::Face(map(f.number))));
    planes += f.planar ? 1 : 0;
    cylinders += f.surface == "cylinder" ? 1 : 0;
    CHECK(f.area > 0);
    if (f.surface == "cylinder") {
      CHECK_FALSE(f.planar);
      CHECK_THAT(f.problem, Contains("not planar"));
    }
  }
  CHECK(planes == 14);
  CHECK(cylinders == 1);
  // Usable: the slab's top and bottom (with the hole), its ten sides (each in its own frame) and the
  // cylinder's two disks (bounded by circles: issue 13); not the cylinder's side (curved).
  const std::vector<int> usable = usable_faces(faces);
  REQUIRE(usable.size() == 14);
  double up = 0, down = 0, disks = 0;
  for (int n : usable) {
    const FaceSummary& f = faces[static_cast<size_t>(n - 1)];
    if (std::fabs(f.normal[2]) < 0.5) continue;  // a side
    if (f.area < 50) {
      CHECK(f.area == Approx(4.0 * M_PI));
      ++disks;
      continue;
    }
    CHECK(f.area == Approx(52.0));
    CHECK(f.normal[0] == Approx(0).margin(1e-12));
    CHECK(f.normal[1] == Approx(0).margin(1e-12));
    (f.normal[2] > 0 ? up : down) += 1;
  }
  CHECK(up == 1);
  CHECK(down == 1);
  CHECK(disks == 2);
}

TEST_CASE("load_input_face takes the face numbered by --face, and says how to choose", "[io][faces][errors]") {
  const std::string path = part_step_file();
  const std::vector<FaceSummary> faces = list_faces(read_shape_file(path));
  const int top = [&] {
    for (const FaceSummary& f : faces) {
      if (f.problem.empty() && f.normal[2] > 0 && f.area > 50) return f.number;
    }
    return 0;
  }();
  REQUIRE(top > 0);
  // Good: the top face, in its plane z = 3, with the hole.
  const InputFace face = load_input_face(path, top);
  CHECK(face.planar.z == Approx(3.0));
  CHECK(face.planar.normal_up);
  CHECK(face.planar.polygon.holes.size() == 1);
  CHECK(polygon_area(face.planar.polygon) == Approx(52.0));
  CHECK(face.source == path + " (Face" + std::to_string(top) + ")");
  // Missing: the message names what the file holds and how to choose.
  REQUIRE_THROWS_WITH(load_input_face(path, 0, "choose one with --face N"),
                      path + ": the file holds a compound with 15 faces; choose one with --face N");
  REQUIRE_THROWS_WITH(load_input_face(path), Contains("15 faces; expected exactly one planar face"));
  // Out of range.
  REQUIRE_THROWS_WITH(load_input_face(path, 16, "choose one with --face N"),
                      path + ": the file has no face 16: it holds a compound with 15 faces (faces 1 to 15); "
                             "choose one with --face N");
  REQUIRE_THROWS_AS(load_input_face(path, -1), InputError);
  // A curved face, and a side face (planar, in another plane: accepted in its own frame).
  for (const FaceSummary& f : faces) {
    if (f.surface == "cylinder") {
      REQUIRE_THROWS_WITH(load_input_face(path, f.number),
                          path + " (Face" + std::to_string(f.number) +
                              "): the face is not planar: its surface is a cylinder");
    } else if (f.planar && f.normal[2] == Approx(0).margin(1e-9)) {
      CHECK(f.problem.empty());
      const InputFace side = load_input_face(path, f.number);
      CHECK(!side.frame.identity());
      CHECK(polygon_area(side.planar.polygon) == Approx(f.area));
    }
  }
}

TEST_CASE("select_face keeps one-face shapes working and names what it found with its article", "[io][faces][errors]") {
  const TopoDS_Face face = occt_face_from_polygon(test::polygon_of(test::l_shape()), 0, true);
  CHECK(select_face(face, "f", 0).IsSame(face));
  CHECK(select_face(face, "f", 1).IsSame(face));
  REQUIRE_THROWS_WITH(select_face(face, "f", 2), "f has no face 2: it is a single face (face 1)");
  REQUIRE_THROWS_WITH(select_face(BRepPrimAPI_MakeBox(1, 2, 3).Shape(), "f", 0),
                      "f holds a solid with 6 faces; expected exactly one planar face");
  for (const test::BadShape& bad : test::bad_shapes()) {
    if (bad.name != "wire-only") continue;
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(bad.shape, TopAbs_EDGE, edges);
    REQUIRE_THROWS_WITH(select_face(edges(1), "f", 0), "f holds an edge with no face; expected a planar face");
    REQUIRE_THROWS_WITH(select_face(bad.shape, "f", 0), "f holds a wire with no face; expected a planar face");
  }
  REQUIRE_THROWS_WITH(select_face(TopoDS_Shape(), "f", 0), "f holds no shape");
}
