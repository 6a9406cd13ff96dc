// The mesh-line strips of a blocked face: the unknowns of interval assignment.
//
// Why strips. In a conformal mesh made only of rectangles every interior node has four right
// angles, so every mesh line runs straight from boundary to boundary. A block corner (a
// T-junction vertex included) is a mesh node, so the horizontal and vertical lines through it
// are mesh lines across the whole face, through the neighbouring blocks, until they reach the
// face's boundary. These forced lines cut the face into "cells": rectangles whose sides are whole
// (no T-junctions: a line ends only on the boundary). Then:
//   - a column strip is a maximal stack of cells with one x-range [x0, x1], joined across their
//     horizontal sides. Every horizontal mesh edge inside it is divided alike, so the strip has
//     ONE interval count n and its vertical mesh lines are x0 + k (x1 - x0) / n, k = 1 .. n-1;
//   - a row strip is the same for y (a maximal row of cells with one y-range).
// A block side is a run of strips and its opposite side is the same run, so opposite sides carry
// nodes at the same positions (not only the same counts); a T-junction's line continues through
// the neighbours; every element is an exact axis-aligned rectangle (scaled Jacobian 1, interior
// valence 4). Every mesh of rectangles conforming to the blocks has this form, so nothing is lost.
//
// Everything is exact integer work on a grid (grid.h): the face's grid plus the blocks'
// coordinates (the same grid for a Decomposition, whose block corners lie on the face's grid).
// Forced lines are runs of interior grid segments through a block corner, strips are unions of
// grid cells.
#pragma once

#include <memory>
#include <vector>

#include "core/geometry/grid_face.h"
#include "core/geometry/point.h"

namespace autoblock {

enum class StripAxis { Column = 0, Row = 1 };

struct Strip {
  StripAxis axis = StripAxis::Column;
  int lo = 0, hi = 0;             // grid indices of its range: xs[lo]..xs[hi] (column) or ys (row)
  double start = 0.0, end = 0.0;  // the range in model coordinates
  double length() const { return end - start; }
};

// A cell: the rectangle where a column strip and a row strip cross.
struct StripCell {
  int column = 0, row = 0;  // strip ids
};

struct StripLayout {
  std::shared_ptr<const Grid> grid;  // the face's grid refined by the blocks' coordinates
  std::vector<Strip> strips;     // column strips and row strips, one id space
  std::vector<StripCell> cells;  // every cell once
  // Per grid cell (i, j), index j * columns + i: its column and row strip, -1 outside the face.
  std::vector<int> cell_column, cell_row;

  int column_of(int i, int j) const { return cell_column[static_cast<size_t>(j * grid->columns() + i)]; }
  int row_of(int i, int j) const { return cell_row[static_cast<size_t>(j * grid->columns() + i)]; }
};

// Inputs:  face on its grid; blocks, a partition of the face into rectangles (a Decomposition's
//          blocks, or any other); boundary_points, points of the face's boundary that are mesh nodes
//          (the face's vertices its polygon leaves out, InputFace::straight_vertices): each forces
//          the lines through it as a block corner does.
// Outputs: the strips, the cells, and the strip of every cell of the layout's grid.
// Throws std::logic_error when the blocks do not partition the face.
StripLayout strip_layout(const GridFace& face, const std::vector<Box>& blocks,
                         const std::vector<Point2>& boundary_points = {});

// Inputs: layout; axis; grid line index (j for a horizontal line y = ys[j], i for x = xs[i]);
//         grid range [from, to) along the line.
// Outputs: the strips that divide that stretch of the line, in order (column strips along a
//          horizontal line, row strips along a vertical one); a strip is taken from the cell on
//          either side that is inside the face. Throws std::logic_error if neither side is.
std::vector<int> strips_along(const StripLayout& layout, StripAxis axis, int line, int from, int to);

// Inputs: strip; intervals n >= 1. Output: its n + 1 node coordinates, start and end exact.
std::vector<double> strip_nodes(const Strip& strip, int intervals);

}  // namespace autoblock
