// Mesh files: Gmsh .msh (format 4.1, ASCII), VTK .vtu (XML, ASCII) and Abaqus/CalculiX .inp.
//
// Coordinates are written with the shortest text that reads back to the same double, so a file
// read back gives the mesh bitwise. Every format keeps the blocks:
//   .msh  one surface entity and one physical group "block_<k>" (dimension 2, tag k) per block;
//         a node belongs to the entity of the first block that uses it; quads are type 3;
//   .vtu  VTK_QUAD cells (type 9) with cell data "block" (1-based) and "scaled_jacobian";
//   .inp  *NODE, then one *ELEMENT, TYPE=CPS4, ELSET=BLOCK_<k> per block, and ELSET=EALL.
// Node and element numbers start at 1 in .msh and .inp (0-based connectivity in .vtu).
#pragma once

#include <array>
#include <string>

#include "core/geometry/placement.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock {

// Where the mesh's plane lies in the model (geometry/placement.h): a front end whose face lies in
// another plane (a CAD model's side face, carried into its own frame for the core) writes the nodes
// where the face is.
using MeshPlacement = Placement;

// Inputs: mesh; placement. Output: the file's text.
std::string gmsh_msh41(const QuadMesh& mesh, const MeshPlacement& placement = {});
std::string vtk_vtu(const QuadMesh& mesh, const MeshPlacement& placement = {});
std::string abaqus_inp(const QuadMesh& mesh, const MeshPlacement& placement = {});

// Inputs: path ending in .msh, .vtu or .inp (any case); mesh; placement. Output: the text of that
// format. Throws InputError for another extension.
std::string mesh_file_text(const std::string& path, const QuadMesh& mesh, const MeshPlacement& placement = {});

// Inputs: path ending in .msh, .vtu or .inp (any case); mesh; placement. Writes the file atomically.
// Throws InputError for another extension or a file that cannot be written.
void write_mesh_file(const std::string& path, const QuadMesh& mesh, const MeshPlacement& placement = {});

// Inputs: path. Output: true when write_mesh_file knows its extension.
bool is_mesh_file_name(const std::string& path);

}  // namespace autoblock
