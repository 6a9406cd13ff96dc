#include "core/env/region_replay.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/geometry/occt_split.h"
#include "core/region/region.h"

namespace autoblock {
namespace {

struct Measure {
  double area = 0.0;
  Point2 centroid;
};

Measure measure(const TopoDS_Face& face) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  const gp_Pnt c = props.CentreOfMass();
  return {props.Mass(), Point2{c.X(), c.Y()}};
}

// The area between the region's loops and the face's arcs: how far a piece's area on the lattice's
// polygon can differ from the true piece's.
double arc_gap_area(const Region& region, const FaceArcs& arcs) {
  double gap = 0.0;
  for (const Ring& ring : region.loops()) {
    for (size_t k = 0; k < ring.size(); ++k) {
      const Point2 a = ring[k], b = ring[(k + 1) % ring.size()];
      const int arc = arcs.arc_of_chord(a, b);
      if (arc >= 0) gap += std::fabs(arc_gap(arcs.arcs[static_cast<size_t>(arc)], a, b).area);
    }
  }
  return gap;
}

}  // namespace

std::vector<TopoDS_Face> replay_region_cuts_occt(const TopoDS_Face& face, const Region& region,
                                                 const RegionDecomposition& decomposition,
                                                 RegionEpisodeOptions options, const FaceArcs* arcs) {
  const bool curved = arcs && !arcs->empty();
  const double gap_area = curved ? arc_gap_area(region, *arcs) : 0.0;

  options.reward = decomposition.reward;
  options.rules = decomposition.rules;
  options.face_rules = false;
  options.max_steps = static_cast<int>(decomposition.cuts.size()) + 1;
  RegionEpisode episode(region, options);
  const double q = region.quantum();
  std::map<int, TopoDS_Face> faces;
  // The whole face: the first part, or the only block when the face is one already.
  faces[episode.running() ? episode.current_part_id() : episode.finished().at(0).id] = face;
  int step = 0;
  for (const RegionCutRecord& record : decomposition.cuts) {
    ++step;
    const std::string where = "replay_region_cuts_occt, cut " + std::to_string(step) + ": ";
    if (!episode.running() || episode.current_part_id() != record.part_id) {
      throw std::logic_error(where + "the cut sequence does not match the face");
    }
    const CutOutcome outcome = episode.outcome_of(record.action);
    if (record.action.kind == RegionAction::Kind::Cut && outcome.pieces.size() >= 2) {
      std::vector<std::pair<Point2, Point2>> segments;
      for (const Chord& c : outcome.chords) {
        segments.emplace_back(c.a, c.b);
        // An end on an arc's polygon lies up to a sagitta off the arc, inside the true face (the
        // polygons are inscribed where the face is inside the circle, circumscribed where it is
        // outside): the cut goes on along the radius to the arc, where the mesh puts that vertex.
        for (const Point2 end : {c.a, c.b}) {
          const int arc = curved ? arcs->arc_of_point(end) : -1;
          if (arc < 0) continue;
          const Point2 on = project_to_circle(end, arcs->arcs[static_cast<size_t>(arc)]);
          if (std::hypot(on.x - end.x, on.y - end.y) > 0.5 * q) segments.emplace_back(end, on);
        }
      }
      // Chord ends lie on the lattice, within q / sqrt(2) of a boundary that is itself within q / sqrt(2)
      // of the true one: gaps up to 1.5 q count as touching. The engine keeps every other vertex farther
      // than 2 q from the chords (region_cut.h).
      const std::vector<TopoDS_Face> pieces = split_face_along_segments(faces.at(record.part_id), segments, 1.5 * q);
      std::vector<Measure> measures;
      for (const TopoDS_Face& p : pieces) measures.push_back(measure(p));
      if (pieces.size() != outcome.pieces.size()) {
        std::string areas = " (areas: OpenCASCADE";
        for (const Measure& m : measures) areas += " " + std::to_string(m.area);
        areas += "; the engine";
        for (const Region& r : outcome.pieces) areas += " " + std::to_string(r.area());
        throw std::logic_error(where + "OpenCASCADE made " + std::to_string(pieces.size()) + " pieces, the engine " +
                               std::to_string(outcome.pieces.size()) + areas + ")");
      }
      std::vector<char> used(pieces.size(), 0);
      const RegionCutRecord& applied = episode.step(record.action, outcome);
      for (size_t k = 0; k < outcome.pieces.size(); ++k) {
        const Region& piece = outcome.pieces[k];
        // Rounding to the lattice moves each boundary point by at most q / 2 (region.h).
        const double area_tolerance = region_perimeter(piece) * q + 1e-9 * piece.area() + gap_area;
        size_t match = pieces.size();
        double best = std::numeric_limits<double>::infinity();
        for (size_t j = 0; j < pieces.size(); ++j) {
          if (used[j] || std::fabs(measures[j].area - piece.area()) > area_tolerance) continue;
          const double d = std::hypot(measures[j].centroid.x - piece.centroid().x, measures[j].centroid.y - piece.centroid().y);
          if (d < best) best = d, match = j;
        }
        if (match == pieces.size()) {
          throw std::logic_error(where + "no OpenCASCADE piece has the area " + std::to_string(piece.area()) +
                                 " of the engine's piece " + std::to_string(k + 1));
        }
        used[match] = 1;
        faces[applied.children.at(k)] = pieces[match];
      }
    } else {
      episode.step(record.action, outcome);
    }
  }
  std::vector<TopoDS_Face> out;
  for (const FinishedRegion& f : decomposition.finished) out.push_back(faces.at(f.id));
  for (const RegionPiece& piece : episode.queue()) out.push_back(faces.at(piece.id));
  if (out.size() != decomposition.finished.size() + decomposition.unfinished.size()) {
    throw std::logic_error("replay_region_cuts_occt: the replay left other parts than the decomposition");
  }
  return out;
}

}  // namespace autoblock
