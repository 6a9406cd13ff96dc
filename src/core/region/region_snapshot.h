// A general face's episode replayed from its action sequence, to a given step: what the workbench's
// step-through panel shows of a general decomposition (the grid engine's twin is
// env/episode_snapshot.h), and the replay a saved document's sequence is checked with.
//
// Actions are given by position, as a report or a saved document holds them (the part's id, the
// kind, the cut's origin and direction in the face's frame); each is checked against the current
// part: its id must be the part's, a cut's origin must lie on the part's boundary (within two
// quanta) and its direction must be a finite non-zero vector, a template needs a convex part. So a
// sequence that does not belong to the face is an InputError, not a wrong picture.
#pragma once

#include <string>
#include <vector>

#include "core/region/region_policy.h"

namespace autoblock {

// One action of a general sequence, by position.
struct RegionActionSpec {
  int part_id = 0;
  RegionAction action;  // kind (cut: full or partial, with origin, direction and forced; or template)
};

// Inputs: records, a general decomposition's cuts. Output: the same actions by position.
std::vector<RegionActionSpec> region_action_specs(const std::vector<RegionCutRecord>& records);

// Inputs: name, "full", "partial" or "template" (action_kind_name). Output: the action's kind (a cut's
//         kind set). Throws InputError for another name.
RegionAction region_action_of_kind(const std::string& name);

struct RegionSnapshotPiece {
  int id = 0;
  bool finished = false;       // set aside (a block or a template); false: a part still queued
  bool is_template = false;    // finished with a template (block.h)
  Region region;               // the face's frame
};

struct RegionSnapshot {
  int step = 0;                              // actions taken so far
  int steps = 0;                             // actions in the whole sequence
  std::vector<RegionSnapshotPiece> pieces;   // finished parts in the order set aside, then queued, front first
  int blocks = 0, templates = 0;             // finished so far
  double return_so_far = 0.0;                // sum of the first `step` rewards
  EpisodeStatus status = EpisodeStatus::Running;

  // The next action (only when has_next).
  bool has_next = false;
  int current_part_id = 0;
  std::vector<Point2> vertices;              // the current part's vertices: outer loop, then each hole
  int chosen_vertex = -1;                    // the cut's origin among them; -1: a point on an edge, or a template
  RegionAction action;
  std::vector<Chord> chords;                 // the segments it cuts (empty when it changes nothing, N = 1)
  double reward = 0.0;
  int n_parts = 0;                           // pieces it leaves (1: nothing changed, or a template)
};

// Inputs:  face, the whole face as a region; actions, a sequence of it; step, in [0, actions.size()];
//          options, as the sequence was made (max_steps is raised to the sequence's length: the
//          engine's last-resort actions run past the cap).
// Outputs: the episode after its first `step` actions. Throws InputError when step is out of range or
//          an action does not belong to the face (see above).
RegionEpisode replay_region_episode(const Region& face, const std::vector<RegionActionSpec>& actions, int step,
                                    RegionEpisodeOptions options = {});

// Inputs and throws as replay_region_episode. Output: the episode after `step` actions, the next one described.
RegionSnapshot region_snapshot(const Region& face, const std::vector<RegionActionSpec>& actions, int step,
                               RegionEpisodeOptions options = {});

// Inputs:  as replay_region_episode, the whole sequence; policy, the name the result reports.
// Outputs: the decomposition the sequence makes (seconds: the replay's). Throws InputError as
//          replay_region_episode does, or when the sequence ends before every part is finished.
RegionDecomposition replay_region_decomposition(const Region& face, const std::vector<RegionActionSpec>& actions,
                                                RegionEpisodeOptions options, const std::string& policy);

}  // namespace autoblock
