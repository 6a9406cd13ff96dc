#include "core/mesh/mesh_pipeline.h"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/env/occt_replay.h"
#include "core/mesh/mapped_mesh.h"

namespace autoblock {
namespace {

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The face's box from its vertices.
Box vertex_box(const TopoDS_Face& face) {
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
  Box box{1e300, 1e300, -1e300, -1e300};
  for (int v = 1; v <= vertices.Extent(); ++v) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
    box.xmin = std::min(box.xmin, p.X());
    box.ymin = std::min(box.ymin, p.Y());
    box.xmax = std::max(box.xmax, p.X());
    box.ymax = std::max(box.ymax, p.Y());
  }
  return box;
}

}  // namespace

double target_size_for(const InputFace& face, double size) {
  return size > 0 ? size : face.grid.size / kDefaultSizeDivisions;
}

MeshResult mesh_decomposition(const InputFace& face, const Decomposition& d, const MeshOptions& options) {
  require_rectilinear(face, "meshing");
  if (!d.complete()) {
    const size_t left = d.unfinished.size();
    throw InputError("the decomposition is incomplete (" + counted(static_cast<long long>(left), "part") +
                     (left == 1 ? " is not a rectangle" : " are not rectangles") + " after " +
                     counted(static_cast<long long>(d.cuts.size()), "cut") + "); meshing needs rectangles only: raise --max-steps or use another policy");
  }
  if (!std::isfinite(options.size) || options.size < 0) throw InputError("the element size must be a positive number");
  MeshResult result;
  result.default_size = !(options.size > 0);
  const double h = target_size_for(face, options.size);

  // Intervals first: an infeasible request fails before the slower CAD work.
  auto start = std::chrono::steady_clock::now();
  result.layout = strip_layout(face.grid, d.blocks);
  IntervalOptions interval_options;
  interval_options.target_size = h;
  interval_options.max_quads = options.max_quads;
  const double tolerance = std::max(face.planar.tolerance, 1e-9 * face.grid.size);
  for (const EdgeIntervals& e : options.fixed) {
    interval_options.fixed.push_back(fixed_intervals_on(result.layout, e.a, e.b, e.intervals, tolerance));
  }
  result.fixed = interval_options.fixed;
  result.intervals = assign_intervals(result.layout, interval_options);
  result.interval_seconds = since(start);

  start = std::chrono::steady_clock::now();
  const std::vector<TopoDS_Face> block_faces = replay_cuts_occt(face.occt, face.grid, d.cuts, options.episode);
  if (block_faces.size() != d.blocks.size()) throw std::logic_error("mesh: the replay gave a different number of blocks");
  for (size_t b = 0; b < d.blocks.size(); ++b) {
    const Box got = vertex_box(block_faces[b]), want = d.blocks[b];
    const double tol = 1e-7 * face.grid.size;
    if (std::fabs(got.xmin - want.xmin) > tol || std::fabs(got.xmax - want.xmax) > tol ||
        std::fabs(got.ymin - want.ymin) > tol || std::fabs(got.ymax - want.ymax) > tol) {
      throw std::logic_error("mesh: replayed block " + std::to_string(b + 1) + " is not the decomposition's");
    }
  }
  result.model = conformal_merge(block_faces);
  result.merge_seconds = since(start);

  start = std::chrono::steady_clock::now();
  result.mesh = mapped_mesh(result.model, d.blocks, face.grid, result.layout, result.intervals, face.planar.z);
  result.mesh_seconds = since(start);

  start = std::chrono::steady_clock::now();
  result.quality = mesh_quality(result.mesh);
  result.conformity = check_conformity(result.mesh, face.planar.polygon);
  result.check_seconds = since(start);
  return result;
}

}  // namespace autoblock
