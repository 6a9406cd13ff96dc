// The tolerance rule for faces, relative to the face's size.
//
// L is the longer side of the face's bounding box. Two coordinates closer than
// tolerance(L) = kRelativeTolerance * L are the same coordinate (they are snapped together); an
// edge along X has |dy| <= tolerance(L); an edge or a gap shorter than tolerance(L) is "tiny" and
// an error. Faces with L < kMinimumFaceSize (in model units) are rejected as too small, and
// coordinates beyond kMaximumCoordinate as too large.
#pragma once

namespace autoblock {

constexpr double kRelativeTolerance = 1e-7;
constexpr double kMinimumFaceSize = 1e-6;
// Coordinates beyond this magnitude are refused: areas and other products of them would overflow.
constexpr double kMaximumCoordinate = 1e100;

inline double tolerance_for_size(double longer_side) { return kRelativeTolerance * longer_side; }

}  // namespace autoblock
