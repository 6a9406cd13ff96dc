#include "core/api/training_job.h"

#include <cstdio>
#include <filesystem>
#include <random>

#include "core/api/learned_runtime.h"
#include "core/common/error.h"
#include "core/io/dataset.h"
#include "core/io/input_face.h"

namespace autoblock {

TrainingSet load_training_set(const std::string& folder, const GeneratedSet& generated, const std::string& what) {
  TrainingSet set;
  if (generated.count > 0) {
    std::mt19937_64 rng(generated.seed);
    for (int k = 0; k < generated.count; ++k) {
      set.faces.push_back(make_grid_face(generate_shape(rng, generated.options).polygon));
      char name[32];
      std::snprintf(name, sizeof name, "generated_%04d", k);
      set.names.push_back(name);
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
    require_rectilinear(face, "training", "learning on such faces is issue 12");
    set.faces.push_back(face.grid);
    set.names.push_back(std::filesystem::path(file).filename().string());
  }
  return set;
}

TrainingOutcome run_training_job(const TrainingJob& job, const TrainingCallbacks& callbacks) {
  return learned_runtime().run_training_job(job, callbacks);
}

}  // namespace autoblock
