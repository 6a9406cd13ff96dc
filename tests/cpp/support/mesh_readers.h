// Readers for the mesh files AutoBlock writes (.msh 4.1 ASCII, .vtu ASCII, .inp), for round trips.
// Independent of the writers: they parse the formats as documented, not the writers' code.
#pragma once

#include <string>

#include "core/mesh/quad_mesh.h"

namespace autoblock::test {

// Inputs: the file's text. Output: the mesh (nodes renumbered 0-based by tag order, quads, blocks
// from the physical group / cell data / element set). Throws std::runtime_error on a format error.
QuadMesh read_msh41(const std::string& text);
QuadMesh read_vtu(const std::string& text);
QuadMesh read_inp(const std::string& text);

// Inputs: path. Output: the file's bytes.
std::string slurp_file(const std::string& path);

}  // namespace autoblock::test
