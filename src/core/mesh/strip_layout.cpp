#include "core/mesh/strip_layout.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace autoblock {
namespace {

class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), size_t{0}); }
  size_t find(size_t a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void join(size_t a, size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<size_t> parent_;
};

int grid_index(const std::vector<double>& values, double v, double tolerance) {
  const auto it = std::lower_bound(values.begin(), values.end(), v - tolerance);
  if (it == values.end() || std::fabs(*it - v) > tolerance) {
    throw std::logic_error("strip_layout: a block corner is not on the face's grid");
  }
  return static_cast<int>(it - values.begin());
}

// The face's grid coordinates plus the blocks' (a block corner off the face's grid, as in a
// hand-made partition, adds a coordinate; one within tolerance of an existing one snaps to it).
std::vector<double> refined(const std::vector<double>& face_values, const std::vector<double>& extra, double tolerance) {
  std::vector<double> values = face_values;
  for (double v : extra) {
    const auto it = std::lower_bound(values.begin(), values.end(), v - tolerance);
    if (it == values.end() || std::fabs(*it - v) > tolerance) values.insert(it, v);
  }
  return values;
}

}  // namespace

StripLayout strip_layout(const GridFace& face, const std::vector<Box>& blocks, const std::vector<Point2>& boundary_points) {
  const Grid& face_grid = *face.grid;
  const double tolerance = 1e-9 * face.size;
  std::vector<double> block_xs, block_ys;
  for (const Box& b : blocks) {
    block_xs.insert(block_xs.end(), {b.xmin, b.xmax});
    block_ys.insert(block_ys.end(), {b.ymin, b.ymax});
  }
  for (const Point2& p : boundary_points) {
    block_xs.push_back(p.x);
    block_ys.push_back(p.y);
  }
  auto grid_ptr = std::make_shared<Grid>();
  grid_ptr->xs = refined(face_grid.xs, block_xs, tolerance);
  grid_ptr->ys = refined(face_grid.ys, block_ys, tolerance);
  const Grid& g = *grid_ptr;
  const int nx = g.columns(), ny = g.rows();
  auto cell = [&](int i, int j) { return static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(i); };
  // Inside: the face's cell holding the refined cell's centre.
  std::vector<char> inside_cell(static_cast<size_t>(nx) * static_cast<size_t>(ny), 0);
  for (int j = 0; j < ny; ++j) {
    const double yc = 0.5 * (g.ys[static_cast<size_t>(j)] + g.ys[static_cast<size_t>(j) + 1]);
    const int fj = static_cast<int>(std::upper_bound(face_grid.ys.begin(), face_grid.ys.end(), yc) - face_grid.ys.begin()) - 1;
    for (int i = 0; i < nx; ++i) {
      const double xc = 0.5 * (g.xs[static_cast<size_t>(i)] + g.xs[static_cast<size_t>(i) + 1]);
      const int fi = static_cast<int>(std::upper_bound(face_grid.xs.begin(), face_grid.xs.end(), xc) - face_grid.xs.begin()) - 1;
      inside_cell[cell(i, j)] = face.whole.contains(fi, fj);
    }
  }
  auto inside = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny && inside_cell[cell(i, j)]; };

  // Block corners as grid points; the blocks must cover the face's cells exactly once.
  std::vector<char> corner(static_cast<size_t>(nx + 1) * static_cast<size_t>(ny + 1), 0);
  auto point = [&](int i, int j) { return static_cast<size_t>(j) * static_cast<size_t>(nx + 1) + static_cast<size_t>(i); };
  std::vector<char> covered(inside_cell.size(), 0);
  for (const Box& b : blocks) {
    const int i0 = grid_index(g.xs, b.xmin, tolerance), i1 = grid_index(g.xs, b.xmax, tolerance);
    const int j0 = grid_index(g.ys, b.ymin, tolerance), j1 = grid_index(g.ys, b.ymax, tolerance);
    for (int i : {i0, i1}) {
      for (int j : {j0, j1}) corner[point(i, j)] = 1;
    }
    for (int j = j0; j < j1; ++j) {
      for (int i = i0; i < i1; ++i) {
        if (!inside(i, j) || covered[cell(i, j)]) throw std::logic_error("strip_layout: the blocks do not partition the face");
        covered[cell(i, j)] = 1;
      }
    }
  }
  if (covered != inside_cell) throw std::logic_error("strip_layout: the blocks do not cover the face");
  for (const Point2& p : boundary_points) corner[point(grid_index(g.xs, p.x, tolerance), grid_index(g.ys, p.y, tolerance))] = 1;

  // Forced lines. Horizontal grid segment (i, j) is [xs[i], xs[i+1]] at y = ys[j]; it is interior
  // when the cells below and above are both inside. A maximal run of interior segments is a chord
  // of the face; it is a mesh line when one of its points is a block corner. Same for vertical.
  std::vector<char> h_line(static_cast<size_t>(nx) * static_cast<size_t>(ny + 1), 0);  // (i, j) -> j*nx + i
  std::vector<char> v_line(static_cast<size_t>(nx + 1) * static_cast<size_t>(ny), 0);  // (i, j) -> j*(nx+1) + i
  for (int j = 1; j < ny; ++j) {
    for (int i = 0; i < nx;) {
      if (!(inside(i, j - 1) && inside(i, j))) {
        ++i;
        continue;
      }
      int e = i;
      while (e < nx && inside(e, j - 1) && inside(e, j)) ++e;
      bool forced = false;
      for (int k = i; k <= e && !forced; ++k) forced = corner[point(k, j)];
      if (forced) {
        for (int k = i; k < e; ++k) h_line[static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(k)] = 1;
      }
      i = e;
    }
  }
  for (int i = 1; i < nx; ++i) {
    for (int j = 0; j < ny;) {
      if (!(inside(i - 1, j) && inside(i, j))) {
        ++j;
        continue;
      }
      int e = j;
      while (e < ny && inside(i - 1, e) && inside(i, e)) ++e;
      bool forced = false;
      for (int k = j; k <= e && !forced; ++k) forced = corner[point(i, k)];
      if (forced) {
        for (int k = j; k < e; ++k) v_line[point(i, k)] = 1;
      }
      j = e;
    }
  }

  // Column strips: cells joined across every interior horizontal segment (stacking keeps the
  // x-range) and across vertical segments that are not mesh lines (same cell). Rows alike.
  const size_t n_cells = static_cast<size_t>(nx) * static_cast<size_t>(ny);
  UnionFind columns(n_cells), rows(n_cells);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (!inside(i, j)) continue;
      if (inside(i + 1, j)) {
        rows.join(cell(i, j), cell(i + 1, j));
        if (!v_line[point(i + 1, j)]) columns.join(cell(i, j), cell(i + 1, j));
      }
      if (inside(i, j + 1)) {
        columns.join(cell(i, j), cell(i, j + 1));
        if (!h_line[static_cast<size_t>(j + 1) * static_cast<size_t>(nx) + static_cast<size_t>(i)]) {
          rows.join(cell(i, j), cell(i, j + 1));
        }
      }
    }
  }

  StripLayout layout;
  layout.grid = grid_ptr;
  layout.cell_column.assign(n_cells, -1);
  layout.cell_row.assign(n_cells, -1);
  std::map<size_t, int> column_id, row_id;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (!inside(i, j)) continue;
      const size_t c = cell(i, j);
      auto [cit, cnew] = column_id.try_emplace(columns.find(c), static_cast<int>(layout.strips.size()));
      if (cnew) layout.strips.push_back(Strip{StripAxis::Column, i, i + 1, 0, 0});
      auto [rit, rnew] = row_id.try_emplace(rows.find(c), static_cast<int>(layout.strips.size()));
      if (rnew) layout.strips.push_back(Strip{StripAxis::Row, j, j + 1, 0, 0});
      Strip& column = layout.strips[static_cast<size_t>(cit->second)];
      Strip& row = layout.strips[static_cast<size_t>(rit->second)];
      column.lo = std::min(column.lo, i);
      column.hi = std::max(column.hi, i + 1);
      row.lo = std::min(row.lo, j);
      row.hi = std::max(row.hi, j + 1);
      layout.cell_column[c] = cit->second;
      layout.cell_row[c] = rit->second;
    }
  }
  // Every strip must have one range throughout (a consequence of the argument above; checked).
  std::map<std::pair<int, int>, char> seen;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (!inside(i, j)) continue;
      const int c = layout.column_of(i, j), r = layout.row_of(i, j);
      const Strip& column = layout.strips[static_cast<size_t>(c)];
      const Strip& row = layout.strips[static_cast<size_t>(r)];
      // Each cell's neighbours within the strip's range belong to the strip: every row of a column
      // strip spans all of [lo, hi) (and every column of a row strip).
      for (int a : {i - 1, i + 1}) {
        if (a >= column.lo && a < column.hi && (!inside(a, j) || layout.column_of(a, j) != c)) {
          throw std::logic_error("strip_layout: a column strip is not a stack");
        }
      }
      for (int b : {j - 1, j + 1}) {
        if (b >= row.lo && b < row.hi && (!inside(i, b) || layout.row_of(i, b) != r)) {
          throw std::logic_error("strip_layout: a row strip is not a row");
        }
      }
      if (seen.emplace(std::make_pair(c, r), 1).second) layout.cells.push_back(StripCell{c, r});
    }
  }
  for (Strip& s : layout.strips) {
    const std::vector<double>& values = s.axis == StripAxis::Column ? g.xs : g.ys;
    s.start = values[static_cast<size_t>(s.lo)];
    s.end = values[static_cast<size_t>(s.hi)];
  }
  return layout;
}

std::vector<int> strips_along(const StripLayout& layout, StripAxis axis, int line, int from, int to) {
  const Grid& g = *layout.grid;
  std::vector<int> result;
  for (int k = from; k < to; ++k) {
    int strip = -1;
    for (int side : {line, line - 1}) {
      const int i = axis == StripAxis::Column ? k : side;
      const int j = axis == StripAxis::Column ? side : k;
      if (strip < 0 && i >= 0 && j >= 0 && i < g.columns() && j < g.rows()) {
        strip = axis == StripAxis::Column ? layout.column_of(i, j) : layout.row_of(i, j);
      }
    }
    if (strip < 0) throw std::logic_error("strips_along: the line is not on the face");
    if (result.empty() || result.back() != strip) result.push_back(strip);
  }
  return result;
}

std::vector<double> strip_nodes(const Strip& strip, int intervals) {
  std::vector<double> nodes(static_cast<size_t>(intervals) + 1);
  const double span = strip.end - strip.start;
  for (int k = 0; k < intervals; ++k) nodes[static_cast<size_t>(k)] = strip.start + span * k / intervals;
  nodes.back() = strip.end;
  return nodes;
}

}  // namespace autoblock
