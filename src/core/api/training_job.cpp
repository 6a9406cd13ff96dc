#include "core/api/training_job.h"

#include <cstdio>
#include <filesystem>
#include <random>

#include "core/api/learned_runtime.h"
#include "core/common/error.h"
#include "core/io/dataset.h"
#include "core/data/arc_generator.h"
#include "core/data/general_generator.h"
#include "core/io/input_face.h"
#include "core/geometry/occt_face.h"

namespace autoblock {

TrainingSet load_training_set(const std::string& folder, const GeneratedSet& generated, const std::string& what) {
  TrainingSet set;
  if (generated.total() > 0) {
    if (generated.count < 0 || generated.general < 0 || generated.arcs < 0) throw InputError("negative count of " + what + " shapes");
    std::mt19937_64 rng(generated.seed);
    char name[32];
    for (int k = 0; k < generated.count; ++k) {
      set.faces.push_back(make_grid_face(generate_shape(rng, generated.options).polygon));
      std::snprintf(name, sizeof name, "generated_%04d", k);
      set.names.push_back(name);
    }
    for (int k = 0; k < generated.general; ++k) {
      GeneralOptions options;
      options.kind = static_cast<GeneralKind>(k % 3);
      options.holes = k % 4 == 3;
      options.max_vertices = 20;
      const GeneralShape shape = generate_general_shape(rng, options);
      const InputFace face = input_face_from_occt(occt_face_from_polygon(RectilinearPolygon{shape.outer, shape.holes}, 0.0, true),
                                                  "generated general face");
      std::snprintf(name, sizeof name, "general_%04d", k);
      if (face.is_general()) {
        set.general.push_back(face.region);
        set.general_names.push_back(name);
      } else {  // a turned union may come out square to the axes
        set.faces.push_back(face.grid);
        set.names.push_back(name);
      }
    }
    for (int k = 0; k < generated.arcs; ++k) {
      const ArcFace arc = generate_arc_face(rng, ArcOptions{});
      set.general.push_back(input_face_from_occt(arc.face, arc.name).region);
      std::snprintf(name, sizeof name, "arcs_%04d", k);
      set.general_names.push_back(name);
    }
    return set;
  }
  if (folder.empty()) throw InputError("no " + what + " data: give a folder of faces or generate shapes");
  std::vector<std::string> files;
  try {
    files = collect_shape_files({folder});
  } catch (const InputError& e) {
    throw InputError(what + " data: " + e.what());
  }
  for (const std::string& file : files) {
    const InputFace face = load_input_face(file);
    if (face.is_general()) {
      set.general.push_back(face.region);
      set.general_names.push_back(std::filesystem::path(file).filename().string());
    } else {
      set.faces.push_back(face.grid);
      set.names.push_back(std::filesystem::path(file).filename().string());
    }
  }
  return set;
}

TrainingOutcome run_training_job(const TrainingJob& job, const TrainingCallbacks& callbacks) {
  return learned_runtime().run_training_job(job, callbacks);
}

}  // namespace autoblock
