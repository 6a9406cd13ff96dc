// A face on its coordinate grid: what the decomposition environment works on.
#pragma once

#include <memory>

#include "core/geometry/grid.h"
#include "core/geometry/part.h"
#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

struct GridFace {
  std::shared_ptr<const Grid> grid;
  Part whole;          // the face as one part
  double size = 0.0;   // longer side of the face's bounding box: the length scale of rewards
};

// Largest number of grid cells a face may have (the grid engine's memory bound).
constexpr long kMaxGridCells = 16L * 1024 * 1024;

// Inputs:  polygon, validated (see validate_polygon.h).
// Outputs: the grid of its corner coordinates and the part made of the cells inside it.
// Throws InputError when the grid would exceed kMaxGridCells.
GridFace make_grid_face(const RectilinearPolygon& polygon);

}  // namespace autoblock
