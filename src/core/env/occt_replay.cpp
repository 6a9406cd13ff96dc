#include "core/env/occt_replay.h"

#include <BRepClass_FaceClassifier.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <gp_Pnt.hxx>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/geometry/occt_split.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {
namespace {

// A point strictly inside the part: the centre of its lowest, leftmost cell.
Point2 inner_point(const Part& part) {
  for (int a = 0; a < part.width_cells(); ++a) {
    const int i = part.i0() + a, j = part.j0();
    if (part.contains(i, j)) {
      const Grid& g = part.grid();
      return Point2{0.5 * (g.xs[static_cast<size_t>(i)] + g.xs[static_cast<size_t>(i) + 1]),
                    0.5 * (g.ys[static_cast<size_t>(j)] + g.ys[static_cast<size_t>(j) + 1])};
    }
  }
  throw std::logic_error("inner_point: empty bottom row");
}

size_t corner_count(const Part& part) {
  size_t n = 0;
  for (const CornerRing& loop : part_boundary(part)) n += loop.size();
  return n;
}

size_t corner_count(const PlanarFace& face) {
  size_t n = face.polygon.outer.size();
  for (const Ring& hole : face.polygon.holes) n += hole.size();
  return n;
}

}  // namespace

std::vector<TopoDS_Face> replay_cuts_occt(const TopoDS_Face& face, const GridFace& grid,
                                          const std::vector<CutRecord>& cuts, EpisodeOptions options) {
  Episode episode(grid, options);
  std::map<int, TopoDS_Face> faces{{0, face}};
  const double area_tolerance = 1e-9 * grid.size * grid.size;
  Bnd_Box bounds;
  BRepBndLib::Add(face, bounds);
  double xmin, ymin, zmin, xmax, ymax, zmax;
  bounds.Get(xmin, ymin, zmin, xmax, ymax, zmax);
  const double z = 0.5 * (zmin + zmax);
  for (const CutRecord& cut : cuts) {
    if (!episode.running() || episode.current_part_id() != cut.part_id) {
      throw std::logic_error("replay_cuts_occt: the cut sequence does not match the face");
    }
    const int vertex = episode.vertex_at(cut.vertex);
    if (vertex < 0) throw std::logic_error("replay_cuts_occt: the cut's vertex is not a corner of its part");
    const Action action{vertex, cut.direction};
    const std::vector<Part> pieces = episode.pieces_of(action);
    const AxisLine line = episode.line_of(action);
    const double coordinate = cut.direction == CutDirection::Vertical ? grid.grid->xs[static_cast<size_t>(line.index)]
                                                                      : grid.grid->ys[static_cast<size_t>(line.index)];
    const std::vector<TopoDS_Face> occt_pieces = split_face_along_line(faces.at(cut.part_id), cut.direction, coordinate);
    const CutRecord& record = episode.step(action);
    const std::string where = "cut " + std::to_string(episode.steps()) + ": ";
    if (occt_pieces.size() != pieces.size()) {
      throw std::logic_error(where + "OpenCASCADE made " + std::to_string(occt_pieces.size()) +
                             " pieces, the grid engine " + std::to_string(pieces.size()));
    }
    if (pieces.size() == 1) continue;
    std::vector<char> used(occt_pieces.size(), 0);
    for (size_t p = 0; p < pieces.size(); ++p) {
      const Point2 inside = inner_point(pieces[p]);
      size_t match = occt_pieces.size();
      for (size_t q = 0; q < occt_pieces.size(); ++q) {
        BRepClass_FaceClassifier classify(occt_pieces[q], gp_Pnt(inside.x, inside.y, z), 1e-9 * grid.size);
        if (classify.State() == TopAbs_IN) match = q;
      }
      if (match == occt_pieces.size() || used[match]) {
        throw std::logic_error(where + "a grid piece has no OpenCASCADE counterpart");
      }
      used[match] = 1;
      const TopoDS_Face& occt_piece = occt_pieces[match];
      if (std::fabs(occt_area(occt_piece) - pieces[p].area()) > area_tolerance ||
          corner_count(planar_face_from_occt(occt_piece)) != corner_count(pieces[p])) {
        throw std::logic_error(where + "OpenCASCADE's piece differs from the grid engine's");
      }
      faces[record.children[p]] = occt_piece;
    }
  }
  std::vector<TopoDS_Face> result;
  for (const Piece& block : episode.blocks()) result.push_back(faces.at(block.id));
  for (const Piece& part : episode.queue()) result.push_back(faces.at(part.id));
  return result;
}

}  // namespace autoblock
