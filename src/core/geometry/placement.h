// Where a face's own frame lies in the model: a point (x, y, z) of the frame is the model's point
// rotation (x, y, z) + translation (row-major rotation). The core works on a face in its frame, where
// the face lies in a plane z = const and, if the face is rectilinear in some directions, its edges run
// along X and Y; results go back to the model through the placement.
#pragma once

#include <array>

#include <gp_Trsf.hxx>

namespace autoblock {

struct Placement {
  std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::array<double, 3> translation{0, 0, 0};
  bool identity() const;
  // Inputs: a point of the frame. Output: the model's point (bitwise the input for the identity).
  std::array<double, 3> apply(double x, double y, double z) const;
  // The transformation frame -> model, and model -> frame, for OpenCASCADE.
  gp_Trsf to_model() const;
  gp_Trsf to_frame() const;
};

}  // namespace autoblock
