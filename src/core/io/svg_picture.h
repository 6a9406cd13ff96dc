// An SVG picture of a decomposition: the blocks in distinct colours inside the face's outline, the
// vertex of every cut numbered in cut order, and a title line.
#pragma once

#include <string>
#include <vector>

#include "core/env/episode.h"
#include "core/geometry/rectilinear_polygon.h"
#include "core/region/region_policy.h"

namespace autoblock {

// Inputs:  polygon, the face; blocks; cuts (their vertices are marked); title (" | " starts a
//          second, smaller line).
// Outputs: the SVG document (y up, as in the model).
std::string decomposition_svg(const RectilinearPolygon& polygon, const std::vector<Box>& blocks,
                              const std::vector<CutRecord>& cuts, const std::string& title);

// Inputs:  face, a general face; d, its decomposition by the general engine; title (as above).
// Outputs: the SVG document: blocks in distinct colours, templates with their quads dashed, parts
//          left unfinished in grey, the origin of every cut numbered in cut order.
std::string region_decomposition_svg(const Region& face, const RegionDecomposition& d, const std::string& title);

// Inputs: width, height (the page); margin, the title's left margin; title (" | " starts a second,
// smaller line). Output: the SVG document's opening: the <svg> element, a white background, the title.
std::string svg_page_start(double width, double height, double margin, const std::string& title);

// Inputs: index. Output: a distinct pastel colour "#rrggbb" (hues a golden angle apart).
std::string block_colour(int index);

}  // namespace autoblock
