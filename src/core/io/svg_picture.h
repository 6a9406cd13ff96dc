// An SVG picture of a decomposition: the blocks in distinct colours inside the face's outline, the
// vertex of every cut numbered in cut order, and a title line.
#pragma once

#include <string>
#include <vector>

#include "core/env/episode.h"
#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

// Inputs:  polygon, the face; blocks; cuts (their vertices are marked); title (" | " starts a
//          second, smaller line).
// Outputs: the SVG document (y up, as in the model).
std::string decomposition_svg(const RectilinearPolygon& polygon, const std::vector<Box>& blocks,
                              const std::vector<CutRecord>& cuts, const std::string& title);

// Inputs: index. Output: a distinct pastel colour "#rrggbb" (hues a golden angle apart).
std::string block_colour(int index);

}  // namespace autoblock
