// Pictures of a mesh over its blocks: SVG (with a title) and PNG (libpng, no text).
//
// Blocks are filled in the colours of the decomposition pictures (svg_picture.h), mesh edges are
// thin dark lines, block sides thicker, the face's outline (holes included) thickest; y points up
// as in the model.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/rectilinear_polygon.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock {

// Inputs: polygon, the face; blocks; mesh; title (" | " starts a second, smaller line).
// Output: the SVG document.
std::string mesh_svg(const RectilinearPolygon& polygon, const std::vector<Box>& blocks, const QuadMesh& mesh,
                     const std::string& title);

// Inputs: polygon; blocks; mesh; longer_side_pixels, the drawing's longer side (without margins).
// Output: the PNG file's bytes.
std::string mesh_png(const RectilinearPolygon& polygon, const std::vector<Box>& blocks, const QuadMesh& mesh,
                     int longer_side_pixels = 1000);

// Inputs: path ending in .svg or .png (any case) and the arguments above. Output: the file's
// contents. Throws InputError for another extension.
std::string mesh_picture(const std::string& path, const RectilinearPolygon& polygon, const std::vector<Box>& blocks,
                         const QuadMesh& mesh, const std::string& title);

}  // namespace autoblock
