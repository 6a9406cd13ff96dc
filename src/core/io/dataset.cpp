#include "core/io/dataset.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/baselines/min_rectangles.h"
#include "core/common/error.h"
#include "core/geometry/grid_face.h"
#include "core/geometry/occt_properties.h"
#include "core/geometry/occt_face.h"
#include "core/io/shape_file.h"
#include "core/io/text_file.h"

namespace autoblock {

namespace fs = std::filesystem;

std::vector<std::string> collect_shape_files(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path + ": no such file or folder");
    if (!fs::is_directory(path, ec)) {
      files.push_back(path);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(path, ec)) {
      if (!entry.is_regular_file()) continue;
      std::string ext = entry.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (ext == ".brep" || ext == ".brp" || ext == ".step" || ext == ".stp") found.push_back(entry.path().string());
    }
    if (found.empty()) throw InputError(path + ": the folder holds no .brep, .step or .stp file");
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

void write_dataset(const std::string& folder, const std::vector<GeneratedShape>& shapes,
                   const nlohmann::json& generator) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (!fs::is_directory(folder, ec)) throw InputError(folder + ": cannot create the folder");
  nlohmann::json index = {{"format", "autoblock-dataset"}, {"version", 1}, {"generator", generator}};
  index["shapes"] = nlohmann::json::array();
  for (size_t k = 0; k < shapes.size(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "shape_%04zu.brep", k);
    const GeneratedShape& shape = shapes[k];
    const TopoDS_Face face = occt_face_from_polygon(shape.polygon, 0.0, true);
    if (!occt_shape_valid(face)) throw std::runtime_error(std::string("generated face ") + name + " is not valid");
    write_shape_file((fs::path(folder) / name).string(), face);
    size_t corners = shape.polygon.outer.size();
    for (const Ring& hole : shape.polygon.holes) corners += hole.size();
    index["shapes"].push_back({{"file", name},
                               {"rectangles", shape.rectangles},
                               {"corners", corners},
                               {"holes", shape.polygon.holes.size()},
                               {"area", polygon_area(shape.polygon)},
                               {"min_blocks", min_rectangles(make_grid_face(shape.polygon).whole)}});
  }
  write_text_file((fs::path(folder) / "index.json").string(), index.dump(2) + "\n");
}

}  // namespace autoblock
