// The text of a Gmsh .msh file, format 4.1 ASCII, from entities that each hold one kind of element
// and form one physical group: the one writer behind the quad (mesh_export.h) and hexahedral
// (hex_export.h) meshes.
//
// Layout: $MeshFormat 4.1 0 8; $PhysicalNames (one per entity: its dimension, its tag, its name);
// $Entities (points, curves, surfaces, volumes: each with its box, its physical group and no bounding
// entities); $Nodes (one block per entity that owns nodes, node tag = index + 1, coordinates as the
// shortest text that reads back to the same double); $Elements (one block per entity with elements,
// tags 1, 2, ... in entity order).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace autoblock {

struct MshEntity {
  int dim = 2;                             // 0..3
  int tag = 1;                             // the entity's tag and its physical group's (per dimension)
  std::string physical;                    // the physical group's name
  int element_type = 3;                    // Gmsh's element type: 3 quadrangle, 5 hexahedron
  std::vector<std::vector<int>> elements;  // each element's nodes, 0-based
  std::vector<int> nodes;                  // the nodes listed under this entity (0-based; every node under one entity)
};

// Inputs: out; v. Appends v's shortest text that reads back to the same double (std::to_chars).
void append_shortest(std::string& out, double v);

// Inputs: out; p; separator. Appends "x<separator>y<separator>z", each as append_shortest writes it.
void append_point(std::string& out, const std::array<double, 3>& p, const char* separator);

// Inputs: points, every node's coordinates; entities, ordered by dimension. Output: the file's text.
std::string msh41_text(const std::vector<std::array<double, 3>>& points, const std::vector<MshEntity>& entities);

// Inputs: entities, their elements set. Sets every entity's nodes: each node goes to the first entity
// whose elements use it.
void assign_msh_nodes(std::vector<MshEntity>& entities, size_t node_count);

}  // namespace autoblock
