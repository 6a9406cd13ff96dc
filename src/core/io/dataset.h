// Data sets on disk: a folder of face files plus an index.json describing them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/data/arc_generator.h"
#include "core/data/general_generator.h"
#include "core/data/shape_generator.h"
#include "core/geometry/grid_face.h"
#include "core/region/region.h"

namespace autoblock {

// Faces to train or test on, with their names (file names, or generated_NNNN).
struct TrainingSet {
  std::vector<GridFace> faces;             // rectilinear faces
  std::vector<std::string> names;
  std::vector<Region> general;             // general faces (edges at any angle, arcs as samples; issue 12)
  std::vector<std::string> general_names;
  size_t size() const { return faces.size() + general.size(); }
};

// Inputs:  paths, files and folders.
// Outputs: the shape files: each file as given, and each folder's .brep, .step and .stp files
//          sorted by name.
// Throws InputError for a missing path or a folder holding no shape file.
std::vector<std::string> collect_shape_files(const std::vector<std::string>& paths);

// Inputs:  folder (created when missing); shapes; generator, how they were made (stored in the
//          index).
// Outputs: folder/shape_0000.brep, ... (faces at z = 0, each checked with BRepCheck_Analyzer) and
//          folder/index.json: {"format": "autoblock-dataset", "version": 1, "generator": ...,
//          "shapes": [{"file", "rectangles", "corners", "holes", "area", "min_blocks"}]}.
void write_dataset(const std::string& folder, const std::vector<GeneratedShape>& shapes,
                   const nlohmann::json& generator);

// Inputs:  folder; shapes, general faces (general_generator.h); generator.
// Outputs: as write_dataset, the index's shapes as {"file", "corners", "holes", "area"}.
void write_general_dataset(const std::string& folder, const std::vector<GeneralShape>& shapes,
                           const nlohmann::json& generator);

// Inputs:  folder; faces with circular arcs (arc_generator.h); generator.
// Outputs: folder/shape_NNNN.brep (the faces as built, checked with BRepCheck_Analyzer) and
//          index.json, the shapes as {"file", "kind", "name", "holes", "arcs" (circular edges),
//          "area" (OpenCASCADE's, of the true face)}.
void write_arc_dataset(const std::string& folder, const std::vector<ArcFace>& faces, const nlohmann::json& generator);

}  // namespace autoblock
