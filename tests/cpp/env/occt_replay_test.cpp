// The grid engine and OpenCASCADE's splitter agree on every cut of many episodes.
#include <catch2/catch.hpp>


#include "core/baselines/baseline_policy.h"
#include "core/env/decomposition.h"
#include "core/env/occt_replay.h"
#include "core/geometry/occt_properties.h"
#include "core/geometry/occt_face.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("replaying decompositions with BRepAlgoAPI_Splitter gives the same blocks", "[env][occt]") {
  for (bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    const auto shapes = test::generated_shapes(40, holes ? 31 : 30, options);
    for (size_t s = 0; s < shapes.size(); ++s) {
      const GridFace face = make_grid_face(shapes[s].polygon);
      const TopoDS_Face occt = occt_face_from_polygon(shapes[s].polygon, 3.0, true);
      for (const std::string name : {"random", "optimal"}) {
        BaselineOptions baseline;
        baseline.seed = s;
        auto policy = make_baseline_policy(name, face.size, baseline);
        const Decomposition d = decompose_face(face, *policy);
        INFO("shape " << s << " holes " << holes << " policy " << name);
        // replay_cuts_occt itself checks piece counts, areas and corner counts at every cut.
        const auto blocks = replay_cuts_occt(occt, face, d.cuts);
        REQUIRE(blocks.size() == d.blocks.size());
        double area = 0;
        for (const TopoDS_Face& block : blocks) {
          REQUIRE(occt_shape_valid(block));
          CHECK(occt_vertex_count(block) == 4);
          area += occt_area(block);
        }
        CHECK(area == Approx(face.whole.area()));
      }
    }
  }
}
