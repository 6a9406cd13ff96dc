// The paper's full cut: an infinite axis-parallel line through a corner, clipped to a part.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/part.h"

namespace autoblock {

// A horizontal cut runs along y = grid.ys[index]; a vertical cut along x = grid.xs[index].
enum class CutDirection { Horizontal = 0, Vertical = 1 };

struct AxisLine {
  CutDirection direction = CutDirection::Horizontal;
  int index = 0;
};

// "horizontal" or "vertical".
std::string direction_name(CutDirection direction);

// Inputs: part, line. Output: true when the line runs through the part's interior somewhere (then
// the cut splits the part into two or more pieces).
bool line_crosses_interior(const Part& part, const AxisLine& line);

// Inputs:  part, line.
// Outputs: the connected pieces of the part on both sides of the line, ordered by their lowest,
//          then leftmost cell. When the line does not cross the interior (it misses the part or
//          only runs along its boundary) the result is the part itself, N = 1.
std::vector<Part> cut_part(const Part& part, const AxisLine& line);

}  // namespace autoblock
