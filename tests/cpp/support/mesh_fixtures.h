// Hand-made block models for the mesh tests: a face and a partition into rectangles given as boxes,
// merged by OpenCASCADE without running a policy.
#pragma once

#include <vector>

#include "core/io/input_face.h"
#include "core/mesh/conformal_merge.h"
#include "core/mesh/interval_assignment.h"
#include "core/mesh/quad_mesh.h"
#include "core/mesh/strip_layout.h"
#include "core/region/region_episode.h"

namespace autoblock::test {

struct HandModel {
  InputFace face;
  std::vector<Box> blocks;
  ConformalBlocks model;
  StripLayout layout;
};

// Inputs: outer ring and holes (any orientation); blocks, a partition of the face into rectangles.
// Output: the face, the merged blocks and their strip layout.
HandModel hand_model(const Ring& outer, const std::vector<Ring>& holes, const std::vector<Box>& blocks);

// Inputs: model; intervals. Output: the mapped mesh.
QuadMesh hand_mesh(const HandModel& model, const IntervalAssignment& intervals);

// The pinwheel: [0,3]^2 cut into four 2 x 1 blocks around the centre square; every corner of the
// centre square is a T-junction.
std::vector<Box> pinwheel_blocks();

// Inputs: model; polygon. Checks (Catch2 CHECKs): every edge belongs to one face on the polygon's
// boundary or to two faces inside it, every vertex on a face's side is a vertex of that face, and
// the faces' areas add up to the polygon's.
void check_conformal_model(const ConformalBlocks& model, const RectilinearPolygon& polygon);

// Inputs: id; ring, a block's outline (four corners); quantum. Output: the finished block (its
//         corners found as block.h finds them; a Catch2 REQUIRE that it has them).
FinishedRegion finished_block(int id, const Ring& ring, double quantum);

}  // namespace autoblock::test
