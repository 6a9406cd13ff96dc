#include "core/io/dataset.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
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

namespace {

// Writes folder/shape_NNNN.brep for each of count faces, face(k, item) making face k and filling its
// index entry (item holds "file"), and folder/index.json.
void write_faces(const std::string& folder, size_t count, const nlohmann::json& generator,
                 const std::function<TopoDS_Face(size_t, nlohmann::json&)>& face_of) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (!fs::is_directory(folder, ec)) throw InputError(folder + ": cannot create the folder");
  nlohmann::json index = {{"format", "autoblock-dataset"}, {"version", 1}, {"generator", generator}};
  index["shapes"] = nlohmann::json::array();
  for (size_t k = 0; k < count; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "shape_%04zu.brep", k);
    nlohmann::json item = {{"file", name}};
    const TopoDS_Face face = face_of(k, item);
    if (!occt_shape_valid(face)) throw std::runtime_error(std::string("generated face ") + name + " is not valid");
    write_shape_file((fs::path(folder) / name).string(), face);
    index["shapes"].push_back(item);
  }
  write_text_file((fs::path(folder) / "index.json").string(), index.dump(2) + "\n");
}

// As above for polygons, each entry with its corners, holes and area, then entry(k, item).
template <class Entry>
void write_polygons(const std::string& folder, const std::vector<RectilinearPolygon>& polygons, const nlohmann::json& generator,
                    Entry entry) {
  write_faces(folder, polygons.size(), generator, [&](size_t k, nlohmann::json& item) {
    const RectilinearPolygon& polygon = polygons[k];
    size_t corners = polygon.outer.size();
    for (const Ring& hole : polygon.holes) corners += hole.size();
    item["corners"] = corners;
    item["holes"] = polygon.holes.size();
    item["area"] = polygon_area(polygon);
    entry(k, item);
    return occt_face_from_polygon(polygon, 0.0, true);
  });
}

}  // namespace

void write_dataset(const std::string& folder, const std::vector<GeneratedShape>& shapes,
                   const nlohmann::json& generator) {
  std::vector<RectilinearPolygon> polygons;
  for (const GeneratedShape& shape : shapes) polygons.push_back(shape.polygon);
  write_polygons(folder, polygons, generator, [&](size_t k, nlohmann::json& item) {
    item["rectangles"] = shapes[k].rectangles;
    item["min_blocks"] = min_rectangles(make_grid_face(shapes[k].polygon).whole);
  });
}

void write_general_dataset(const std::string& folder, const std::vector<GeneralShape>& shapes,
                           const nlohmann::json& generator) {
  std::vector<RectilinearPolygon> polygons;
  for (const GeneralShape& shape : shapes) polygons.push_back(RectilinearPolygon{shape.outer, shape.holes});
  write_polygons(folder, polygons, generator, [](size_t, nlohmann::json&) {});
}

void write_arc_dataset(const std::string& folder, const std::vector<ArcFace>& faces, const nlohmann::json& generator) {
  write_faces(folder, faces.size(), generator, [&](size_t k, nlohmann::json& item) {
    const ArcFace& f = faces[k];
    item["kind"] = arc_kind_name(f.kind);
    item["name"] = f.name;
    item["holes"] = f.holes;
    item["arcs"] = f.arcs;
    item["area"] = occt_area(f.face);
    return f.face;
  });
}

}  // namespace autoblock
