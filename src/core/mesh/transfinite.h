// Transfinite interpolation (Coons patch) of a block from its four logical sides.
#pragma once

#include <vector>

#include "core/geometry/point.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock {

// Inputs:  the four sides as node chains, bottom P00 -> P10, top P01 -> P11, left P00 -> P01,
//          right P10 -> P11, sharing their corner nodes; bottom and top have nu + 1 >= 2 nodes,
//          left and right nv + 1 >= 2.
// Outputs: the (nu + 1) (nv + 1) nodes of the structured grid, node (i, j) at j (nu + 1) + i; the
//          boundary nodes are the given ones, exactly. Interior node (i, j) is the Boolean sum
//            P = (1-v) B(u) + v T(u) + (1-u) L(v) + u R(v) - bilinear(corners)
//          with u_i, v_j the mean normalised arc lengths of the opposite sides. It is evaluated as
//          "x: B + v (T - B) plus the left/right correction" and "y: L + u (R - L) plus the
//          bottom/top correction", the same sum in an order that reproduces a straight side's
//          coordinates bitwise: on a rectangle whose opposite sides carry equal node positions,
//          node (i, j) is exactly (B_i.x, L_j.y), so elements are exact rectangles.
// Throws std::invalid_argument when the chain sizes or corners do not match.
std::vector<Point2> transfinite_grid(const std::vector<Point2>& bottom, const std::vector<Point2>& top,
                                     const std::vector<Point2>& left, const std::vector<Point2>& right);

// The same grid from the sides as curves: interior node (i, j) is the Coons patch of the four sides,
// each a polyline through its nodes parametrised by normalised arc length, at the (u, v) where the
// grid line from bottom node i to top node i (u running from ub_i to ut_i as v goes 0 to 1) meets the
// line from left node j to right node j. Where opposite sides space their nodes differently (a long
// side with a fillet facing a short arc), the discrete sum above can fold; this one follows the
// patch, which does not fold where the sides' shapes do not force it. Throws as transfinite_grid.
std::vector<Point2> transfinite_grid_by_length(const std::vector<Point2>& bottom, const std::vector<Point2>& top,
                                               const std::vector<Point2>& left, const std::vector<Point2>& right);

// Inputs:  mesh, holding the sides' nodes; the four sides as node ids into mesh.nodes, oriented as
//          transfinite_grid's (bottom P00 -> P10, top P01 -> P11, left P00 -> P01, right P10 -> P11,
//          corners shared); block, the quads' block number; by_length, transfinite_grid_by_length
//          instead of transfinite_grid.
// Outputs: the block's interior nodes appended to mesh.nodes (transfinite_grid's), and its quads
//          appended row by row, counter-clockwise when the sides are.
// Throws std::invalid_argument as transfinite_grid.
void add_mapped_block(QuadMesh& mesh, const std::vector<int>& bottom, const std::vector<int>& top,
                      const std::vector<int>& left, const std::vector<int>& right, int block,
                      bool by_length = false);

}  // namespace autoblock
