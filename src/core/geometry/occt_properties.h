// Measures of OpenCASCADE shapes: validity (BRepCheck_Analyzer), area, vertex count.
#pragma once

#include <TopoDS_Shape.hxx>

namespace autoblock {

// Inputs: shape. Output: true when BRepCheck_Analyzer finds it valid.
bool occt_shape_valid(const TopoDS_Shape& shape);

// Inputs: shape. Output: the total area of its faces.
double occt_area(const TopoDS_Shape& shape);

// Inputs: shape. Output: the number of distinct vertices in it.
int occt_vertex_count(const TopoDS_Shape& shape);

}  // namespace autoblock
