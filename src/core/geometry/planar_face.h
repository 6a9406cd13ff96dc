// A supported input face: a validated rectilinear polygon lying in the plane z = const.
#pragma once

#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

struct PlanarFace {
  RectilinearPolygon polygon;  // model coordinates, validated (see validate_polygon.h)
  double z = 0.0;              // the face's plane
  bool normal_up = true;       // the face's normal is +Z (false: -Z)
  double tolerance = 0.0;      // the snapping tolerance used (see tolerance.h)
};

}  // namespace autoblock
