#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "core/geometry/occt_face.h"
#include "core/io/input_face.h"
#include "core/io/face_selection.h"
#include "core/io/shape_file.h"
#include "support/bad_shapes.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {
std::string write_text(const std::string& folder, const std::string& name, const std::string& text) {
  const std::string path = folder + "/" + name;
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST_CASE("read_shape_file names missing, empty, garbage and unknown files", "[io][errors]") {
  const std::string folder = test::temporary_folder("shape-file");
  REQUIRE_THROWS_WITH(read_shape_file(folder + "/missing.brep"), Contains("no such file"));
  REQUIRE_THROWS_WITH(read_shape_file(write_text(folder, "empty.brep", "")), Contains("the file is empty"));
  REQUIRE_THROWS_WITH(read_shape_file(write_text(folder, "garbage.brep", "hello, not a shape\n")),
                      Contains("not a readable BREP file"));
  REQUIRE_THROWS_WITH(read_shape_file(write_text(folder, "garbage.step", "ISO-10303-21;\ngarbage\n")),
                      Contains("not a readable STEP file"));
  REQUIRE_THROWS_WITH(read_shape_file(write_text(folder, "shape.iges", "x")), Contains("unknown file type"));
  REQUIRE_THROWS_WITH(read_shape_file(folder), Contains("is a directory"));
}

TEST_CASE("faces round-trip through BREP and STEP files and BREP text", "[io]") {
  const std::string folder = test::temporary_folder("round-trip");
  const RectilinearPolygon polygon = test::polygon_of(test::square3(), {test::centre_hole()});
  const TopoDS_Face face = occt_face_from_polygon(polygon, 2.5, true);
  for (const std::string name : {"face.brep", "face.step", "face.stp"}) {
    const std::string path = folder + "/" + name;
    write_shape_file(path, face);
    const InputFace input = load_input_face(path);
    CHECK(input.planar.z == Approx(2.5));
    CHECK(polygon_area(input.planar.polygon) == Approx(8.0));
    CHECK(input.planar.polygon.holes.size() == 1);
    CHECK(input.grid.whole.area() == Approx(8.0));
  }
  const InputFace from_text = input_face_from_occt(select_face(read_brep_text(write_brep_text(face)), "text", 0), "text");
  CHECK(from_text.grid.whole.area() == Approx(8.0));
  REQUIRE_THROWS_WITH(read_brep_text("  \n"), Contains("empty"));
  REQUIRE_THROWS_WITH(read_brep_text("CASCADE nonsense"), Contains("not readable BREP"));
}

TEST_CASE("write_shape_file refuses unknown types and missing folders without leaving files", "[io][errors]") {
  const std::string folder = test::temporary_folder("write");
  const TopoDS_Face face = occt_face_from_polygon(test::polygon_of(test::l_shape()), 0, true);
  REQUIRE_THROWS_WITH(write_shape_file(folder + "/out.obj", face), Contains("unknown output file type"));
  REQUIRE_THROWS_WITH(write_shape_file(folder + "/no/such/out.brep", face), Contains("does not exist"));
  CHECK(std::filesystem::is_empty(folder));
}

TEST_CASE("every class of bad shape gets its own clear error", "[io][errors]") {
  for (const test::BadShape& bad : test::bad_shapes()) {
    INFO(bad.name);
    REQUIRE_THROWS_WITH(input_face_from_occt(select_face(bad.shape, "the file", 0), bad.name), Contains(bad.expected));
  }
}
