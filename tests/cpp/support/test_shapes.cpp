#include "support/test_shapes.h"

#include <filesystem>
#include <mutex>
#include <random>
#include <system_error>
#include <vector>

#include "core/geometry/circular_arc.h"
#include "core/geometry/tolerance.h"
#include "core/geometry/validate_polygon.h"
#include "core/region/region_candidates.h"
#include "core/region/region_cut.h"

namespace autoblock::test {

RectilinearPolygon polygon_of(const Ring& outer, const std::vector<Ring>& holes) {
  std::vector<RawRing> rings{{"outer wire", outer}};
  for (size_t h = 0; h < holes.size(); ++h) rings.push_back({"inner wire " + std::to_string(h + 1), holes[h]});
  return validate_rings(rings);
}

GridFace grid_face_of(const Ring& outer, const std::vector<Ring>& holes) {
  return make_grid_face(polygon_of(outer, holes));
}

Ring l_shape() { return {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}; }
Ring square3() { return {{0, 0}, {3, 0}, {3, 3}, {0, 3}}; }
Ring centre_hole() { return {{1, 1}, {2, 1}, {2, 2}, {1, 2}}; }

std::vector<GeneratedShape> generated_shapes(int count, std::uint64_t seed, const GeneratorOptions& options) {
  std::mt19937_64 rng(seed);
  std::vector<GeneratedShape> shapes;
  for (int k = 0; k < count; ++k) shapes.push_back(generate_shape(rng, options));
  return shapes;
}

Ring round_hole(Point2 c, double r) {
  CircularArc arc;
  arc.center = c;
  arc.radius = r;
  arc.sweep = -2.0 * M_PI;
  arc.outside = true;
  Ring ring = polygonise_arc(arc);
  ring.pop_back();  // a full circle ends where it starts
  return ring;
}

RectilinearPolygon general_polygon(std::uint64_t seed, GeneralKind kind, bool holes) {
  std::mt19937_64 rng(seed);
  GeneralOptions options;
  options.kind = kind;
  options.holes = holes;
  const GeneralShape shape = generate_general_shape(rng, options);
  return RectilinearPolygon{shape.outer, shape.holes};
}

Region region_of(const RectilinearPolygon& polygon) {
  return Region(polygon.outer, polygon.holes, tolerance_for_size(ring_bbox(polygon.outer).longer_side()));
}

std::vector<Region> face_and_first_pieces(const Region& face, size_t count) {
  std::vector<Region> parts{face};
  for (const RegionAction& a : region_candidates(face)) {
    if (parts.size() > count) break;
    if (a.kind != RegionAction::Kind::Cut) continue;
    const CutOutcome o = cut_region(face, a.cut);
    if (o.pieces.size() >= 2) parts.insert(parts.end(), o.pieces.begin(), o.pieces.end());
  }
  return parts;
}

namespace {

// The folders made by temporary_folder, removed when the test program exits (they used to be left
// in /tmp: thousands after a few runs).
struct TemporaryFolders {
  std::mutex mutex;
  std::vector<std::filesystem::path> folders;
  ~TemporaryFolders() {
    for (const std::filesystem::path& folder : folders) {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  }
};

TemporaryFolders& temporary_folders() {
  static TemporaryFolders folders;
  return folders;
}

}  // namespace

std::string temporary_folder(const std::string& name) {
  namespace fs = std::filesystem;
  std::random_device random;
  const fs::path folder = fs::temp_directory_path() / ("autoblock-test-" + name + "-" + std::to_string(random()));
  fs::create_directories(folder);
  TemporaryFolders& all = temporary_folders();
  const std::lock_guard<std::mutex> lock(all.mutex);
  all.folders.push_back(folder);
  return folder.string();
}

}  // namespace autoblock::test
