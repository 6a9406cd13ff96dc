// Random general faces (straight edges at any angle), for tests, benchmarks and training.
//
// Kinds:
//   polygon    a random simple polygon with V vertices: star-shaped around its centre, the
//              vertices at sorted random angles and random radii in [0.45, 1] R;
//   turned     a union of rectangles (shape_generator.h) turned by a random angle;
//   chamfered  a union of rectangles with some of its convex corners cut at 45 degrees.
// With holes: a polygon gets one or two convex holes (4 to 6 vertices) well inside it; a union gets
// the rectangular holes of shape_generator.h (turned with it).
// Every face is redrawn until its corners are all at least min_corner_degrees.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

enum class GeneralKind { Polygon, Turned, Chamfered };

// "polygon", "turned", "chamfered"; and back (throws InputError for other names).
std::string general_kind_name(GeneralKind kind);
GeneralKind general_kind_by_name(const std::string& name);

struct GeneralOptions {
  GeneralKind kind = GeneralKind::Polygon;
  int min_vertices = 5;  // polygon: V ~ uniform[min_vertices, max_vertices]
  int max_vertices = 12;
  int min_rects = 2;     // turned and chamfered: rectangles united
  int max_rects = 6;
  bool holes = false;
  double size = 100.0;   // the face's outer radius (polygon) or grid unit x 10 (unions)
  double min_corner_degrees = 20.0;
};

struct GeneralShape {
  Ring outer;               // counter-clockwise
  std::vector<Ring> holes;  // clockwise
};

// Inputs: rng; options (3 <= min_vertices <= max_vertices, 1 <= min_rects <= max_rects, size > 0).
// Outputs: one face of the kind asked. Throws InputError for invalid options.
GeneralShape generate_general_shape(std::mt19937_64& rng, const GeneralOptions& options);

}  // namespace autoblock
