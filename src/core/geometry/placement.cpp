#include "core/geometry/placement.h"

namespace autoblock {

bool Placement::identity() const {
  return rotation == std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1} && translation == std::array<double, 3>{0, 0, 0};
}

std::array<double, 3> Placement::apply(double x, double y, double z) const {
  if (identity()) return {x, y, z};  // bitwise: no arithmetic on the identity
  const auto& r = rotation;
  return {r[0] * x + r[1] * y + r[2] * z + translation[0], r[3] * x + r[4] * y + r[5] * z + translation[1],
          r[6] * x + r[7] * y + r[8] * z + translation[2]};
}

gp_Trsf Placement::to_model() const {
  gp_Trsf t;
  if (identity()) return t;
  const auto& r = rotation;
  t.SetValues(r[0], r[1], r[2], translation[0], r[3], r[4], r[5], translation[1], r[6], r[7], r[8], translation[2]);
  return t;
}

gp_Trsf Placement::to_frame() const { return to_model().Inverted(); }

}  // namespace autoblock
