// Training a policy for a front end (the Python binding, and so the FreeCAD workbench's Train panel
// and AutoBlock.train): the data (folders of faces or generated shapes), a fresh run or one resumed
// from its checkpoint, a report per episode and a stop request between episodes, and at the end the
// policy file, the CSV log and the curves picture. The CLI's `autoblock train` is the same flow
// with a terminal around it. The work runs in the learned-policy runtime (learned_runtime.h),
// loaded on first use; this header needs no LibTorch.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/data/shape_generator.h"
#include "core/io/dataset.h"
#include "core/sac/episode_record.h"

namespace autoblock {

// Shapes made by the generators instead of read from a folder: unions of rectangles
// (shape_generator.h) and, for the lookahead agent (issue 12), general faces: polygons of 5-20
// vertices, turned and chamfered unions (general_generator.h, the kinds in turn, a quarter with
// holes) and faces with circular arcs (arc_generator.h, scales 0.1-100).
struct GeneratedSet {
  int count = 0;    // unions of rectangles (0: none; all three 0: use the folder)
  std::uint64_t seed = 0;
  GeneratorOptions options;
  int general = 0;  // general faces with straight edges
  int arcs = 0;     // faces with circular arcs
  int total() const { return count + general + arcs; }
};

struct TrainingJob {
  std::string output;            // the policy file written when the run completes
  std::string checkpoint;        // empty: output + ".checkpoint"
  bool resume = false;           // continue the run saved in the checkpoint
  std::string init;              // a fresh run starting from this policy's weights (a shipped name or
                                 // a file; the same agent kind and value network), not from random ones
  std::string train_folder;      // a folder of .brep/.step faces, or
  GeneratedSet train_generate;   // generated shapes (count > 0)
  std::string test_folder;
  GeneratedSet test_generate;
  int episodes = 1500;           // total, counting those done before a resume
  std::uint64_t seed = 0;
  std::string reward = "paper";  // reward preset (a fresh run; a resumed run keeps its own)
  std::string agent = "lookahead";
  int threads = 1;               // LibTorch threads while training
  int eval_every = 25;           // episodes between test evaluations and checkpoints
  int max_steps = 0;
  // Beyond the defaults of the agent kind (sac_config.h); 0, negative or empty: the default.
  std::string value_network;     // "small" | "paper"
  std::string bootstrap;         // paper agent: "graph" | "critics"
  int batch_size = 0;
  double lr_final = 0.0;         // lookahead agent: learning rate's fraction left at the end
  double weight_average = -1.0;  // lookahead agent: moving-average decay of the deployed weights
  int deploy_views = 0;          // lookahead agent: symmetric views averaged when deployed
  std::vector<std::string> settings;  // "key=value" on the agent's configuration, applied last
                                      // (sac_config.h with_settings; a fresh run only, but
                                      // deploy_views and deploy_top_k also on a resume)
  std::string log;               // CSV log; empty: the output's stem + ".csv"
  std::string curves;            // curves picture, .svg or .png; empty: the output's stem + "-curves.svg"
  std::string description;       // what the policy file records as the training data (empty: derived)
};

struct TrainingCallbacks {
  // After every episode (also, first, for every episode of a resumed run's history, with
  // earlier = true).
  std::function<void(const EpisodeRecord& record, bool earlier)> on_episode;
  // Asked between episodes: true stops the run (a checkpoint is written).
  std::function<bool()> should_stop;
  // A line on what the run is doing before its first episode (the data read, the reference returns
  // computed: the search on every general test face, up to its time limit each).
  std::function<void(const std::string& line)> on_status;
};

struct TrainingOutcome {
  bool cancelled = false;        // stopped before the last episode
  int episodes_done = 0;
  int episodes = 0;
  std::string reward;            // the run's reward preset
  std::string policy_file;       // empty when cancelled
  std::string checkpoint;
  std::string log;               // CSV, one line per episode
  std::string curves;            // SVG
  double final_test_return = 0.0;
  double optimal_test_return = 0.0;  // the exact search's mean return on the test set (reference; on
                                     // general faces the general engine's search)
  double greedy_test_return = 0.0;   // greedy's, likewise
  int episodes_to_95 = -1;           // first evaluated episode reaching the 95 % mark (-1: never)
  double seconds_to_95 = -1.0;
  std::string rule_95;               // how that mark was measured
  double wall_seconds = 0.0;         // the run's training time, resumed runs included
};

// Inputs:  folder (when generated.total() == 0) or generated; what ("training" or "test"), for messages.
// Outputs: the set's faces: rectilinear ones in faces, the others (edges at other angles, arcs) in
//          general. Throws InputError for a missing folder, an unreadable or unsupported
//          face (naming the file), or an empty set.
TrainingSet load_training_set(const std::string& folder, const GeneratedSet& generated, const std::string& what);

// Inputs:  job; callbacks.
// Outputs: what the run did and wrote. Loads the learned-policy runtime. Throws InputError for bad data or options (a missing output
//          folder, a missing or foreign checkpoint, an unknown reward preset or agent, an initial
//          policy of another agent kind or network, or init with resume); exceptions
//          thrown by the callbacks pass through (after the checkpoint is written).
TrainingOutcome run_training_job(const TrainingJob& job, const TrainingCallbacks& callbacks);

}  // namespace autoblock
