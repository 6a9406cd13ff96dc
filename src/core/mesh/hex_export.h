// Hexahedral mesh files: Gmsh .msh (format 4.1, ASCII), VTK .vtu (XML, ASCII) and Abaqus/CalculiX
// .inp, in the model's coordinates. Every format keeps the blocks and the solid's faces:
//   .msh  one volume entity and physical group "block_<k>" (dimension 3, tag k) per block, holding its
//         hexahedra (type 5); one surface entity and physical group "face_<f>" (dimension 2, tag f) per
//         face f of the solid, holding the boundary quads on it (type 3, outward); a node belongs to the
//         volume of the first block that uses it;
//   .vtu  VTK_HEXAHEDRON cells (type 12) with cell data "block" (1-based) and "scaled_jacobian";
//   .inp  *NODE (NSET=NALL), one *ELEMENT, TYPE=C3D8 (or C3D8I), ELSET=BLOCK_<k> per block, ELSET=EALL,
//         and per face f of the solid a node set FACE_<f> and an element-face surface SFACE_<f>
//         (so boundary conditions and loads can be applied by name).
// Node and element numbers start at 1 in .msh and .inp (0-based connectivity in .vtu).
#pragma once

#include <string>

#include "core/mesh/hex_mesh.h"

namespace autoblock {

// Inputs: mesh. Output: the file's text.
std::string gmsh_msh41(const HexMesh& mesh);
std::string vtk_vtu(const HexMesh& mesh);
// element_type: "C3D8" (full integration) or "C3D8I" (incompatible modes: no shear locking in bending).
std::string abaqus_inp(const HexMesh& mesh, const std::string& element_type = "C3D8");

// Inputs: path ending in .msh, .vtu or .inp (any case); mesh; element_type for .inp. Output: the text
// of that format. Throws InputError for another extension.
std::string mesh_file_text(const std::string& path, const HexMesh& mesh, const std::string& element_type = "C3D8");

}  // namespace autoblock
