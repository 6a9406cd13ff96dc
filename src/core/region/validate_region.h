// Turn the boundary loops of a general planar face (straight edges at any angle) into a valid Region,
// or say exactly what is wrong and where.
#pragma once

#include <vector>

#include "core/geometry/validate_polygon.h"
#include "core/region/region.h"

namespace autoblock {

// Corners sharper than this (the angle between a corner's two edges) are refused: no quadrilateral
// mesh can be usable there (its best scaled Jacobian would be below sin 5 degrees = 0.087).
constexpr double kMinimumCornerDegrees = 5.0;

// Inputs:  rings, the face's wires (any order, any orientation; the outer one is the one of largest
//          area); *tolerance_out (optional) receives the tolerance used.
// Outputs: the face as a Region on its lattice (quantum = the tolerance, tolerance.h): outer ring
//          counter-clockwise, holes clockwise, collinear vertices merged.
// Throws InputError, naming the wire, the edge or corner and its coordinates, when: the checks of
// face_tolerance fail; two consecutive vertices are closer than the tolerance (an edge shorter
// than it); a corner is sharper than kMinimumCornerDegrees (or the boundary doubles back); two
// edges that are not neighbours cross, touch or come closer than the tolerance (a sliver); a hole
// lies outside the outer wire or inside another hole.
Region validate_general_rings(const std::vector<RawRing>& rings, double* tolerance_out = nullptr);

}  // namespace autoblock
