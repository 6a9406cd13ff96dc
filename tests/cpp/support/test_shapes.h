// Shapes and helpers shared by the tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/data/general_generator.h"
#include "core/data/shape_generator.h"
#include "core/geometry/grid_face.h"
#include "core/geometry/rectilinear_polygon.h"
#include "core/region/region.h"

namespace autoblock::test {

// Inputs: outer and holes as corner lists (any orientation). Output: the validated grid face.
GridFace grid_face_of(const Ring& outer, const std::vector<Ring>& holes = {});
RectilinearPolygon polygon_of(const Ring& outer, const std::vector<Ring>& holes = {});

// The L-shape (0,0) (2,0) (2,1) (1,1) (1,2) (0,2).
Ring l_shape();
// A square [0,3]^2 with the hole [1,2]^2.
Ring square3();
Ring centre_hole();

// Inputs: centre c, radius r. Output: a round hole as the region engine reads one: the circle's
// samples (polygonise_arc), clockwise, the closing point left out.
Ring round_hole(Point2 c, double r);

// Inputs: count, seed, options. Output: that many generated shapes.
std::vector<GeneratedShape> generated_shapes(int count, std::uint64_t seed, const GeneratorOptions& options);

// Inputs: seed, kind, holes. Output: one generated general shape (general_generator.h) as a polygon.
RectilinearPolygon general_polygon(std::uint64_t seed, GeneralKind kind, bool holes);

// Inputs: polygon. Output: it as a region, on the lattice of its size's tolerance (tolerance.h).
Region region_of(const RectilinearPolygon& polygon);

// Inputs: face, a region; count. Output: the face, then the pieces of its first candidate cuts
// (region_candidates order) that split it, until more than count parts are listed: parts of many
// shapes for property tests of cuts and scores.
std::vector<Region> face_and_first_pieces(const Region& face, size_t count);

// A fresh empty temporary folder, removed with its contents when the test program exits.
std::string temporary_folder(const std::string& name);

}  // namespace autoblock::test
