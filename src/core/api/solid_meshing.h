// Mesh a swept solid with hexahedra in one call: detect its caps and sweep (solid/swept_solid.h),
// decompose and quad-mesh the bottom cap like any face (face_meshing.h: every policy and option),
// sweep the quad mesh layer by layer (mesh/hex_mesh.h), measure its quality and check it
// independently (hex_quality.h, hex_conformity.h). The CLI's `mesh` calls this for a solid.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/api/face_meshing.h"
#include "core/mesh/hex_conformity.h"
#include "core/mesh/hex_mesh.h"
#include "core/mesh/hex_quality.h"
#include "core/solid/prism_blocks.h"
#include "core/solid/swept_solid.h"

namespace autoblock {

// The most hexahedra a request may make.
constexpr long kMaxMeshHexes = 5'000'000;

struct SolidMeshOptions {
  MeshOptions cap;       // the cap's mesh; cap.size 0: the solid's longest bounding-box side / 20
  int layers = 0;        // layers along the sweep; 0: the sweep's length over the element size, rounded (at least 1)
  double grading = 1.0;  // each layer's thickness over the previous one's (1: uniform)
};

struct SolidMeshing {
  SweptSolid solid;
  FaceMeshing cap;            // the bottom cap's decomposition and quad mesh
  HexMesh mesh;
  HexMeshQuality quality;
  HexConformity conformity;   // the independent check
  double target_size = 0.0;   // h
  bool default_size = false;  // h was derived from the solid's size
  double grading = 1.0;
  double seconds = 0.0;       // everything, wall time (no file I/O)
  double sweep_seconds = 0.0, check_seconds = 0.0;
  size_t blocks() const { return cap.blocks(); }
};

// What a mesh file holds: one face (as today) or a swept solid.
struct MeshInput {
  bool is_solid = false;
  InputFace face;     // when !is_solid
  SweptSolid solid;   // when is_solid
};

// Inputs:  path (.brep, .step, .stp); face_number (0: the file's only face or its solid); how_to_choose
//          (see load_input_face).
// Outputs: the solid when face_number is 0 and the file holds one solid (or a shell of several faces,
//          holds_one_solid); otherwise the face, exactly as load_input_face gives it. One read.
// Throws InputError (shape_file.h, swept_solid.h, input_face.h).
MeshInput load_mesh_input(const std::string& path, int face_number = 0, const std::string& how_to_choose = "");

// Inputs:  solid; settings (the cap's policy and options); options.
// Outputs: everything above, returned even when the conformity check fails (the caller reports it).
// Throws InputError for a bad policy or request (the cap's, or layers, grading, more than
//          kMaxMeshHexes hexahedra).
SolidMeshing mesh_swept_solid(const SweptSolid& solid, const DecomposeSettings& settings, SolidMeshOptions options);

// Inputs: meshing. Output: the blocks as conformal prisms (prism_blocks.h), model coordinates.
PrismBlocks solid_meshing_blocks(const SolidMeshing& meshing);

// Inputs: solid; decomposition, of solid.cap made with occt_blocks (decompose_input_face: the merged
// blocks in the model's coordinates).
// Output: the blocks (and any part left unfinished) swept into prisms sharing their faces.
PrismBlocks swept_blocks(const SweptSolid& solid, const FaceDecomposition& decomposition);

// Inputs: meshing. Throws when the independent check failed: InputError ("<source>: OpenCASCADE's checker
// finds the solid invalid ..." or "<source>: face N's OpenCASCADE tolerance T is not small against its
// shortest edge ...") when the solid itself is at fault (BRepCheck_Analyzer, or a face's tolerance at
// least half its shortest edge), else std::runtime_error ("the hexahedral mesh failed the conformity
// check: ...").
void require_conformal(const SolidMeshing& meshing);

// Inputs: input, the file name; meshing.
// Output: the JSON report: {"input", "kind": "solid", "policy", "blocks", "nodes", "hexahedra", "layers",
//         "grading", "target_size", "default_size", "caps": [bottom, top] (face numbers), "sweep": [x, y, z],
//         "sweep_angle" (degrees between the sweep and the caps' normal), "volume", "area",
//         "quality": {"min_scaled_jacobian", "mean_scaled_jacobian", "max_aspect_ratio",
//         "mean_aspect_ratio", "max_skew", "edges", "interior_edges", "irregular_edges",
//         "irregular_interior_edges"}, "conformal", "conformity": {"interior_faces", "boundary_faces",
//         "overused_faces", "misoriented_faces", "inverted_hexahedra", "mismatched_faces", "hex_volume",
//         "solid_volume", "boundary_area", "solid_area", "problem"}, "seconds", "timing": {"cap",
//         "sweep", "checks"}, "cap": the cap's face report (face_meshing_json)}.
nlohmann::json solid_meshing_json(const std::string& input, const SolidMeshing& meshing);

// Inputs: meshing; title. Output: an isometric SVG picture of the hexahedral mesh's boundary, blocks
// coloured.
std::string solid_meshing_svg(const SolidMeshing& meshing, const std::string& title);

}  // namespace autoblock
