#include "core/mesh/interval_assignment.h"

#include <glpk.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/common/format.h"

namespace autoblock {
namespace {

struct ProblemDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

double deviation(double length, int k, double h) { return std::fabs(length / k - h) / h; }

// The largest count a strip may be given before the program is built (guards int overflow).
constexpr double kMaxStripIntervals = 1e7;

}  // namespace

FixedIntervals fixed_intervals_on(const StripLayout& layout, Point2 a, Point2 b, int intervals, double tolerance) {
  const Grid& g = *layout.grid;
  FixedIntervals fixed;
  fixed.intervals = intervals;
  fixed.what = "edge " + format_point(a.x, a.y) + "-" + format_point(b.x, b.y);
  auto index = [&](const std::vector<double>& values, double v) {
    const auto it = std::lower_bound(values.begin(), values.end(), v - tolerance);
    if (it == values.end() || std::fabs(*it - v) > tolerance) {
      throw InputError(fixed.what + ": " + format_number(v) + " is not a corner coordinate of the face");
    }
    return static_cast<int>(it - values.begin());
  };
  if (intervals < 1) throw InputError(fixed.what + ": the interval count must be at least 1");
  const int ia = index(g.xs, a.x), ib = index(g.xs, b.x), ja = index(g.ys, a.y), jb = index(g.ys, b.y);
  const bool horizontal = ja == jb && ia != ib, vertical = ia == ib && ja != jb;
  if (!horizontal && !vertical) throw InputError(fixed.what + ": not a stretch parallel to X or Y");
  const StripAxis axis = horizontal ? StripAxis::Column : StripAxis::Row;
  const int line = horizontal ? ja : ia, from = horizontal ? std::min(ia, ib) : std::min(ja, jb);
  const int to = horizontal ? std::max(ia, ib) : std::max(ja, jb);
  try {
    fixed.strips = strips_along(layout, axis, line, from, to);
  } catch (const std::logic_error&) {
    throw InputError(fixed.what + ": not on the face");
  }
  const Strip& first = layout.strips[static_cast<size_t>(fixed.strips.front())];
  const Strip& last = layout.strips[static_cast<size_t>(fixed.strips.back())];
  if (first.lo != from || last.hi != to) {
    throw InputError(fixed.what + ": ends inside a mesh strip; end it at a block corner or where a mesh line crosses");
  }
  return fixed;
}

void check_quad_limit(double quads, bool estimated, double h, long max_quads) {
  const double limit = static_cast<double>(max_quads);
  if (estimated ? quads > 1.5 * limit + 16 : quads > limit) {
    throw InputError("element size " + format_number(h) + " would need " + (estimated ? "about " : "") +
                     (quads > 1e18 ? std::string("too many") : std::to_string(static_cast<long long>(quads))) +
                     " quadrilaterals (limit " + std::to_string(max_quads) + "); choose a larger size");
  }
}

long quad_count(const StripLayout& layout, const std::vector<int>& intervals) {
  long quads = 0;
  for (const StripCell& c : layout.cells) {
    quads += static_cast<long>(intervals[static_cast<size_t>(c.column)]) * intervals[static_cast<size_t>(c.row)];
  }
  return quads;
}

IntervalAssignment assign_intervals(const StripLayout& layout, const IntervalOptions& options) {
  const double h = options.target_size;
  if (!(h > 0) || !std::isfinite(h)) {
    throw InputError("the element size must be a positive number, not " + format_number(h));
  }
  const size_t n_strips = layout.strips.size();
  if (n_strips == 0) throw std::logic_error("assign_intervals: no strips");
  // A quick bound before building anything: the cells' area over h^2 is about the quad count.
  double estimate = 0;
  for (const StripCell& c : layout.cells) {
    estimate += std::max(1.0, layout.strips[static_cast<size_t>(c.column)].length() / h) *
                std::max(1.0, layout.strips[static_cast<size_t>(c.row)].length() / h);
  }
  for (const Strip& s : layout.strips) {
    if (s.length() / h > kMaxStripIntervals) estimate = 1e300;
  }
  check_quad_limit(estimate, true, h, options.max_quads);

  // Candidate windows.
  std::vector<int> lo(n_strips), hi(n_strips);
  for (size_t s = 0; s < n_strips; ++s) {
    const double g = layout.strips[s].length() / h;
    lo[s] = std::max(1, static_cast<int>(std::floor(g)) - 1);
    hi[s] = std::max(1, static_cast<int>(std::ceil(g))) + 1;
  }
  for (const FixedIntervals& f : options.fixed) {
    if (f.strips.empty()) throw std::logic_error("assign_intervals: a fixed count without strips");
    if (f.intervals < static_cast<int>(f.strips.size())) {
      throw InputError(f.what + " cannot have " + counted(f.intervals, "interval") + ": mesh lines divide it into " +
                       counted(static_cast<long long>(f.strips.size()), "strip") + ", each needing at least one");
    }
    for (int s : f.strips) {
      lo[static_cast<size_t>(s)] = 1;
      hi[static_cast<size_t>(s)] = f.intervals;
    }
  }
  for (const FixedIntervals& f : options.fixed) {  // the tightest count bounds a strip
    for (int s : f.strips) hi[static_cast<size_t>(s)] = std::min(hi[static_cast<size_t>(s)], f.intervals);
  }

  glp_term_out(GLP_OFF);
  std::unique_ptr<glp_prob, ProblemDeleter> problem(glp_create_prob());
  glp_prob* lp = problem.get();
  glp_set_obj_dir(lp, GLP_MIN);
  // Column 1: t. Then y_{s,k}.
  std::vector<int> first_column(n_strips);
  int columns = 1;
  for (size_t s = 0; s < n_strips; ++s) {
    first_column[s] = columns + 1;
    columns += hi[s] - lo[s] + 1;
  }
  glp_add_cols(lp, columns);
  glp_set_col_bnds(lp, 1, GLP_LO, 0.0, 0.0);
  glp_set_obj_coef(lp, 1, 1.0);
  const double mean_weight = 0.01 / static_cast<double>(n_strips);
  for (size_t s = 0; s < n_strips; ++s) {
    for (int k = lo[s]; k <= hi[s]; ++k) {
      const int col = first_column[s] + k - lo[s];
      glp_set_col_kind(lp, col, GLP_BV);
      glp_set_obj_coef(lp, col, mean_weight * deviation(layout.strips[s].length(), k, h));
    }
  }
  // Rows: choice (= 1) and bound (t - sum d y >= 0) per strip, then the fixed counts.
  const int rows = static_cast<int>(2 * n_strips + options.fixed.size());
  glp_add_rows(lp, rows);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  auto entry = [&](int row, int col, double value) {
    ia.push_back(row);
    ja.push_back(col);
    ar.push_back(value);
  };
  for (size_t s = 0; s < n_strips; ++s) {
    const int choice = static_cast<int>(2 * s + 1), bound = choice + 1;
    glp_set_row_bnds(lp, choice, GLP_FX, 1.0, 1.0);
    glp_set_row_bnds(lp, bound, GLP_LO, 0.0, 0.0);
    entry(bound, 1, 1.0);
    for (int k = lo[s]; k <= hi[s]; ++k) {
      const int col = first_column[s] + k - lo[s];
      entry(choice, col, 1.0);
      entry(bound, col, -deviation(layout.strips[s].length(), k, h));
    }
  }
  for (size_t f = 0; f < options.fixed.size(); ++f) {
    const int row = static_cast<int>(2 * n_strips + f + 1);
    glp_set_row_bnds(lp, row, GLP_FX, options.fixed[f].intervals, options.fixed[f].intervals);
    for (int s : options.fixed[f].strips) {
      const size_t su = static_cast<size_t>(s);
      for (int k = lo[su]; k <= hi[su]; ++k) entry(row, first_column[su] + k - lo[su], k);
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());

  glp_iocp parameters;
  glp_init_iocp(&parameters);
  parameters.presolve = GLP_ON;
  parameters.msg_lev = GLP_MSG_OFF;
  parameters.tm_lim = static_cast<int>(std::min(1e9, std::max(1.0, options.time_limit * 1000.0)));
  const int code = glp_intopt(lp, &parameters);
  const int status = glp_mip_status(lp);
  auto fixed_list = [&] {
    std::string list;
    for (const FixedIntervals& f : options.fixed) {
      list += (list.empty() ? "" : "; ") + f.what + " = " + std::to_string(f.intervals);
    }
    return list;
  };
  if (code == GLP_ENOPFS || status == GLP_NOFEAS) {
    throw InputError("the fixed interval counts cannot all hold (" + fixed_list() +
                     "): opposite sides of every block must get equal counts");
  }
  if (status != GLP_OPT && status != GLP_FEAS) {
    throw std::runtime_error("GLPK found no interval assignment (glp_intopt returned " + std::to_string(code) + ")");
  }

  IntervalAssignment result;
  result.target_size = h;
  result.optimal = status == GLP_OPT;
  result.intervals.assign(n_strips, 0);
  for (size_t s = 0; s < n_strips; ++s) {
    for (int k = lo[s]; k <= hi[s]; ++k) {
      if (glp_mip_col_val(lp, first_column[s] + k - lo[s]) > 0.5) result.intervals[s] = k;
    }
    if (result.intervals[s] < 1) throw std::runtime_error("GLPK's solution leaves a strip without intervals");
    const double d = deviation(layout.strips[s].length(), result.intervals[s], h);
    result.mean_relative_deviation += d / static_cast<double>(n_strips);
    if (d > result.max_relative_deviation || result.worst_strip < 0) {
      result.max_relative_deviation = d;
      result.worst_strip = static_cast<int>(s);
    }
  }
  result.max_deviation = result.max_relative_deviation * h;
  for (const FixedIntervals& f : options.fixed) {  // the solution must honour every fixed count
    long total = 0;
    for (int s : f.strips) total += result.intervals[static_cast<size_t>(s)];
    if (total != f.intervals) throw std::runtime_error("GLPK's solution breaks a fixed count");
  }
  result.quads = quad_count(layout, result.intervals);
  check_quad_limit(static_cast<double>(result.quads), false, h, options.max_quads);
  return result;
}

}  // namespace autoblock
