// An episode replayed to a given step, for showing a decomposition cut by cut (the workbench's
// step-through panel): the pieces at that step as polygons, the part the policy cuts next, its
// vertices, the chosen vertex and the cut line.
//
// Cuts are given by position (the part's id, the vertex's model coordinates, the direction), as a
// report or a saved document holds them; each is matched to a corner of the current part, so a cut
// sequence that does not belong to the face is an error, not a wrong picture.
#pragma once

#include <string>
#include <vector>

#include "core/env/decomposition.h"
#include "core/env/episode.h"
#include "core/geometry/grid_face.h"
#include "core/geometry/rectilinear_polygon.h"

namespace autoblock {

// One cut of a sequence, by position.
struct CutSpec {
  int part_id = 0;
  Point2 vertex;
  CutDirection direction = CutDirection::Horizontal;
};

// Inputs: cuts, a decomposition's records. Output: the same cuts by position.
std::vector<CutSpec> cut_specs(const std::vector<CutRecord>& cuts);

struct SnapshotPiece {
  int id = 0;                    // the piece's id (0: the face itself; see Piece)
  bool block = false;            // a rectangle set aside (false: a part still queued)
  RectilinearPolygon polygon;    // model coordinates, outer counter-clockwise, holes clockwise
};

struct Segment {
  Point2 a, b;
};

struct EpisodeSnapshot {
  int step = 0;                        // cuts made so far
  int steps = 0;                       // cuts in the whole sequence
  std::vector<SnapshotPiece> pieces;   // blocks in the order set aside, then queued parts, front first
  int blocks = 0;                      // rectangles set aside so far
  double return_so_far = 0.0;          // sum of Eq. (1) over the first `step` cuts
  EpisodeStatus status = EpisodeStatus::Running;

  // The next cut, the one the policy chose at this step (only when has_next).
  bool has_next = false;
  int current_part_id = 0;             // the part it cuts (front of the queue)
  std::vector<Point2> vertices;        // that part's model vertices (Episode::current_vertices order)
  int chosen_vertex = -1;              // index into vertices
  CutDirection direction = CutDirection::Horizontal;
  std::vector<Segment> line;           // where the line crosses the part's interior (along its
                                       // boundary when the cut changes nothing, N = 1)
  double reward = 0.0;                 // Eq. (1) of the next cut
  int n_parts = 0;                     // pieces it leaves
};

// Inputs:  face; cuts, a whole cut sequence of the face; step, in [0, cuts.size()]; options, the
//          episode options the sequence was made with.
// Outputs: the episode after `step` cuts, with the next cut described.
// Throws InputError when step is out of range or a cut does not match the face (its part is not the
// current part, or its vertex is not one of that part's corners).
EpisodeSnapshot episode_snapshot(const GridFace& face, const std::vector<CutSpec>& cuts, int step,
                                 EpisodeOptions options = {});

// Inputs:  face; cuts, a cut sequence of the face; step, in [0, cuts.size()]; options, as for
//          episode_snapshot.
// Outputs: the episode after its first `step` cuts (running when a cut follows), e.g. to ask a
//          learned policy about that step. Throws InputError as episode_snapshot does.
Episode replay_episode(const GridFace& face, const std::vector<CutSpec>& cuts, int step, EpisodeOptions options = {});

// Inputs:  face; cuts, a whole cut sequence of the face (as a report or a saved document holds it);
//          options, as the sequence was made; policy, the name the result reports.
// Outputs: the decomposition the sequence makes, as decompose_face reports it (seconds: the replay's).
// Throws InputError when a cut does not match the face or the sequence ends before the episode does.
Decomposition replay_decomposition(const GridFace& face, const std::vector<CutSpec>& cuts, EpisodeOptions options,
                                   const std::string& policy);

// Inputs: part. Output: its boundary as a polygon in model coordinates.
RectilinearPolygon part_polygon(const Part& part);

}  // namespace autoblock
