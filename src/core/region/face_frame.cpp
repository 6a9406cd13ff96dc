#include "core/region/face_frame.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/geometry/grid_face.h"
#include "core/geometry/validate_polygon.h"

namespace autoblock {

Point2 FaceFrame::to_frame(Point2 p) const {
  const double c = std::cos(angle), s = std::sin(angle), x = p.x - centre.x, y = p.y - centre.y;
  return {c * x + s * y, -s * x + c * y};
}

Point2 FaceFrame::to_global(Point2 p) const {
  const double c = std::cos(angle), s = std::sin(angle);
  return {centre.x + c * p.x - s * p.y, centre.y + s * p.x + c * p.y};
}

std::optional<FaceFrame> rectilinear_frame(const Region& face) {
  if (face.is_empty()) return std::nullopt;
  // The candidate axis: the mean direction of all edges folded into [0, pi / 2) (the circular mean of
  // four times their angles, weighted by squared length, so long edges, whose directions the lattice
  // disturbs least, count most).
  double sx = 0.0, sy = 0.0;
  for (int k = 0; k < face.loop_count(); ++k) {
    const Ring& ring = face.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) {
      const double dx = ring[(i + 1) % ring.size()].x - ring[i].x, dy = ring[(i + 1) % ring.size()].y - ring[i].y;
      const double w = dx * dx + dy * dy, t = 4.0 * std::atan2(dy, dx);
      sx += w * std::cos(t);
      sy += w * std::sin(t);
    }
  }
  double angle = std::atan2(sy, sx) / 4.0;
  if (angle < 0.0) angle += M_PI / 2.0;
  if (angle >= M_PI / 2.0) angle = 0.0;
  const Ring& outer = face.outer();
  FaceFrame frame{angle, outer[0]};
  // Every edge must run along X or Y in the frame, within twice the quantum at its ends (each end
  // may lie q / sqrt(2) off the exact turn).
  const double q = face.quantum();
  for (int k = 0; k < face.loop_count(); ++k) {
    const Ring& ring = face.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2 a = frame.to_frame(ring[i]), b = frame.to_frame(ring[(i + 1) % ring.size()]);
      if (std::fabs(a.x - b.x) > 2.0 * q && std::fabs(a.y - b.y) > 2.0 * q) return std::nullopt;
    }
  }
  // An axis-aligned face keeps its coordinates (angle exactly 0).
  bool axis_aligned = true;
  for (int k = 0; k < face.loop_count() && axis_aligned; ++k) {
    const Ring& ring = face.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % ring.size()];
      if (a.x != b.x && a.y != b.y) axis_aligned = false;
    }
  }
  if (axis_aligned) frame.angle = 0.0;
  return frame;
}

RectilinearPolygon polygon_in_frame(const Region& face, const FaceFrame& frame) {
  // Turned coordinates that should be equal differ by up to twice the quantum: snap them together
  // first (coordinates of one line of the frame), then validate as any rectilinear face.
  std::vector<std::vector<Point2>> loops;
  std::vector<double> xs, ys;
  for (int k = 0; k < face.loop_count(); ++k) {
    std::vector<Point2> loop;
    for (const Point2& p : face.loop(k)) {
      loop.push_back(frame.angle == 0.0 ? p : frame.to_frame(p));
      xs.push_back(loop.back().x);
      ys.push_back(loop.back().y);
    }
    loops.push_back(std::move(loop));
  }
  const double gap = 2.5 * face.quantum();
  const std::map<double, double> sx = snap_map(xs, gap), sy = snap_map(ys, gap);
  std::vector<RawRing> rings;
  for (size_t k = 0; k < loops.size(); ++k) {
    RawRing raw{k == 0 ? "outer wire" : "wire " + std::to_string(k + 1), {}};
    for (const Point2& p : loops[k]) raw.points.push_back({sx.at(p.x), sy.at(p.y)});
    rings.push_back(std::move(raw));
  }
  return validate_rings(rings);
}

Decomposition decompose_in_frame(const Region& face, const FaceFrame& frame, Policy& policy, EpisodeOptions options,
                                 std::vector<Region>* blocks) {
  const GridFace grid = make_grid_face(polygon_in_frame(face, frame));
  Decomposition d = decompose_face(grid, policy, options);
  if (blocks) {
    blocks->clear();
    for (const Box& b : d.blocks) {
      Ring ring{{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}};
      if (frame.angle != 0.0) {
        for (Point2& p : ring) p = frame.to_global(p);
      }
      blocks->push_back(Region(ring, {}, face.quantum()));
    }
  }
  return d;
}

}  // namespace autoblock
