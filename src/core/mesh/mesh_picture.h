// A picture of a mesh over its blocks, as SVG (raster/picture_file.h writes it as SVG or PNG).
//
// Blocks are filled in the colours of the decomposition pictures (svg_picture.h), mesh edges are
// thin dark lines, block sides thicker, the face's outline (holes included) thickest; y points up
// as in the model. A mesh whose quads carry their parts (QuadMesh::quad_block) is drawn from itself:
// each part filled within the outline of its quads, its sides (edges between quads of two parts) and
// the face's outline (edges of one quad) along the mesh's edges, so that an arc is drawn through the
// mesh's nodes on it rather than as the parts' coarse polygon. Otherwise (no quads) the rings given
// are drawn, the face's holes filled white over the blocks: a part finished around a hole (the
// O-grid template) is given by its outer ring, which would paint the hole over.
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

// Inputs: loops, the face's outer loop and holes (edges at any angle); blocks, the parts' outlines
//         (a template is one part); mesh; title. Output: the SVG document, drawn as above.
std::string mesh_svg(const std::vector<Ring>& loops, const std::vector<Ring>& blocks, const QuadMesh& mesh,
                     const std::string& title);

}  // namespace autoblock
