#include "core/mesh/edge_intervals.h"

#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/region/region.h"

namespace autoblock {
namespace {

struct GlpkProblem {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

// f(n) = max(g / n, n / g) - 1 (see the header).
double size_factor(double g, double n) { return std::max(g / n, n / g) - 1.0; }

// The largest count the program may give an edge (guards int overflow).
constexpr double kMaxEdgeIntervals = 1e7;

}  // namespace

int side_intervals(const ModelSide& side, const std::vector<int>& intervals) {
  int total = 0;
  for (int e : side.edges) total += intervals[static_cast<size_t>(e)];
  return total;
}

long quad_count(const BlockModel& model, const std::vector<int>& intervals) {
  long quads = 0;
  for (const ModelBlock& b : model.blocks) {
    quads += static_cast<long>(side_intervals(b.sides[0], intervals)) * side_intervals(b.sides[1], intervals);
  }
  return quads;
}

FixedIntervals fixed_edge_intervals(const BlockModel& model, Point2 a, Point2 b, int intervals, double tolerance) {
  FixedIntervals fixed;
  fixed.intervals = intervals;
  fixed.what = "edge " + format_point(a.x, a.y) + "-" + format_point(b.x, b.y);
  if (intervals < 1) throw InputError(fixed.what + ": the interval count must be at least 1");
  auto is_vertex = [&](Point2 p) {
    return std::any_of(model.vertices.begin(), model.vertices.end(),
                       [&](const Point2& v) { return std::hypot(v.x - p.x, v.y - p.y) <= tolerance; });
  };
  if (!is_vertex(a) || !is_vertex(b)) {
    throw InputError(fixed.what + ": its ends must be block corners or T-junctions (vertices of the block model)");
  }
  double covered = 0.0;
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& edge = model.edges[e];
    const Point2 p = model.vertices[static_cast<size_t>(edge.a)], q = model.vertices[static_cast<size_t>(edge.b)];
    if (segment_distance(p, a, b) <= tolerance && segment_distance(q, a, b) <= tolerance) {
      fixed.strips.push_back(static_cast<int>(e));
      covered += edge.length;
    }
  }
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  if (fixed.strips.empty() || std::fabs(covered - length) > tolerance * static_cast<double>(2 + fixed.strips.size())) {
    throw InputError(fixed.what + ": not a straight stretch of block sides or of the face's boundary");
  }
  return fixed;
}

IntervalAssignment assign_edge_intervals(const BlockModel& model, const IntervalOptions& options) {
  const double h = options.target_size;
  if (!(h > 0) || !std::isfinite(h)) {
    throw InputError("the element size must be a positive number, not " + format_number(h));
  }
  const size_t n_edges = model.edges.size();
  if (n_edges == 0) throw std::logic_error("assign_edge_intervals: no edges");
  // A quick bound before building anything: each block's sides over h.
  double estimate = 0.0;
  for (const ModelBlock& b : model.blocks) {
    estimate += std::max(1.0, std::max(model.side_length(b.sides[0]), model.side_length(b.sides[2])) / h) *
                std::max(1.0, std::max(model.side_length(b.sides[1]), model.side_length(b.sides[3])) / h);
  }
  for (const ModelEdge& e : model.edges) {
    if (e.length / h > kMaxEdgeIntervals) estimate = 1e300;
  }
  check_quad_limit(estimate, true, h, options.max_quads);
  for (const FixedIntervals& f : options.fixed) {
    if (f.intervals < static_cast<int>(f.strips.size())) {
      throw InputError(f.what + " cannot have " + counted(f.intervals, "interval") + ": block corners divide it into " +
                       counted(static_cast<long long>(f.strips.size()), "edge") + ", each needing at least one");
    }
  }

  glp_term_out(GLP_OFF);
  std::unique_ptr<glp_prob, GlpkProblem> problem(glp_create_prob());
  glp_prob* lp = problem.get();
  glp_set_obj_dir(lp, GLP_MIN);
  // Columns: 1 T; then per edge n_e (2 + 2e) and t_e (3 + 2e).
  const int columns = static_cast<int>(1 + 2 * n_edges);
  glp_add_cols(lp, columns);
  glp_set_col_bnds(lp, 1, GLP_LO, 0.0, 0.0);
  glp_set_obj_coef(lp, 1, 1.0);
  const double mean_weight = 0.01 / static_cast<double>(n_edges);
  auto n_col = [](size_t e) { return static_cast<int>(2 + 2 * e); };
  auto t_col = [](size_t e) { return static_cast<int>(3 + 2 * e); };
  for (size_t e = 0; e < n_edges; ++e) {
    glp_set_col_kind(lp, n_col(e), GLP_IV);
    int least = std::max(1, options.min_intervals);
    if (e < options.edge_minimum.size()) least = std::max(least, options.edge_minimum[e]);
    glp_set_col_bnds(lp, n_col(e), GLP_DB, least, std::max<double>(least, kMaxEdgeIntervals));
    glp_set_col_bnds(lp, t_col(e), GLP_LO, 0.0, 0.0);
    const bool targeted = e < options.edge_target.size() && options.edge_target[e] > 0.0;
    glp_set_obj_coef(lp, t_col(e), mean_weight + (targeted ? options.edge_target_weight : 0.0));
  }
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  int rows = 0;
  auto add_row = [&](int type, double lo, double hi) {
    glp_add_rows(lp, 1);
    glp_set_row_bnds(lp, ++rows, type, lo, hi);
    return rows;
  };
  auto entry = [&](int row, int col, double value) {
    ia.push_back(row);
    ja.push_back(col);
    ar.push_back(value);
  };
  for (size_t e = 0; e < n_edges; ++e) {
    double g = model.edges[e].length / h;
    if (e < options.edge_target.size()) g = std::max(g, options.edge_target[e]);
    // t_e - slope n_e >= intercept for the secant between consecutive breakpoints, and T - t_e >= 0.
    // Breakpoints: every integer down to 10, then 10 % apart down to 1 (between sparse breakpoints the
    // secant lies above f_e: there the program sees a slightly larger deviation than the true one).
    std::vector<int> breakpoints{std::max(1, static_cast<int>(std::ceil(g)))};
    while (breakpoints.back() > 1) {
      const int k = breakpoints.back();
      breakpoints.push_back(k <= 10 ? k - 1 : std::min(k - 1, static_cast<int>(std::floor(0.9 * k))));
    }
    breakpoints.insert(breakpoints.begin(), breakpoints.front() + 1);
    for (size_t i = 0; i + 1 < breakpoints.size(); ++i) {
      const int k1 = breakpoints[i], k0 = breakpoints[i + 1];
      const double f0 = size_factor(g, k0), f1 = size_factor(g, k1), slope = (f1 - f0) / (k1 - k0);
      const int row = add_row(GLP_LO, f0 - slope * k0, 0.0);
      entry(row, t_col(e), 1.0);
      entry(row, n_col(e), -slope);
    }
    const int beyond = add_row(GLP_LO, -1.0, 0.0);
    entry(beyond, t_col(e), 1.0);
    entry(beyond, n_col(e), -1.0 / g);
    const int max_row = add_row(GLP_LO, 0.0, 0.0);
    entry(max_row, 1, 1.0);
    entry(max_row, t_col(e), -1.0);
  }
  // Opposite sides: equal totals (an edge on both sides of a block cancels out).
  for (const ModelBlock& b : model.blocks) {
    for (int pair = 0; pair < 2; ++pair) {
      std::vector<double> coefficient(n_edges, 0.0);
      for (int e : b.sides[static_cast<size_t>(pair)].edges) coefficient[static_cast<size_t>(e)] += 1.0;
      for (int e : b.sides[static_cast<size_t>(pair + 2)].edges) coefficient[static_cast<size_t>(e)] -= 1.0;
      const int row = add_row(GLP_FX, 0.0, 0.0);
      for (size_t e = 0; e < n_edges; ++e) {
        if (coefficient[e] != 0.0) entry(row, n_col(e), coefficient[e]);
      }
    }
  }
  for (const FixedIntervals& f : options.fixed) {
    const int row = add_row(GLP_FX, f.intervals, f.intervals);
    for (int e : f.strips) entry(row, n_col(static_cast<size_t>(e)), 1.0);
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());

  // Feasibility first, on the equalities alone (opposite sides, fixed counts) within the counts'
  // bounds: the deviation rows can always be met, so the program is feasible exactly when these are,
  // and GLPK's presolve decides them at once, where the whole program's simplex can take tens of
  // seconds to find it infeasible (blocks whose counts contradict, a web of templates). Feasible
  // equalities with integer bounds admit integer counts (scale a rational solution).
  bool feasible = true;
  {
    std::unique_ptr<glp_prob, GlpkProblem> equalities(glp_create_prob());
    glp_copy_prob(equalities.get(), lp, GLP_OFF);
    std::vector<int> drop{0};
    for (int row = 1; row <= rows; ++row) {
      if (glp_get_row_type(equalities.get(), row) != GLP_FX) drop.push_back(row);
    }
    if (drop.size() > 1) glp_del_rows(equalities.get(), static_cast<int>(drop.size()) - 1, drop.data());
    for (int col = 1; col <= columns; ++col) glp_set_obj_coef(equalities.get(), col, 0.0);
    glp_smcp simplex;
    glp_init_smcp(&simplex);
    simplex.msg_lev = GLP_MSG_OFF;
    simplex.presolve = GLP_ON;
    const int code = glp_simplex(equalities.get(), &simplex);
    feasible = !(code == GLP_ENOPFS || (code == 0 && glp_get_status(equalities.get()) == GLP_NOFEAS));
  }

  glp_iocp parameters;
  glp_init_iocp(&parameters);
  parameters.presolve = GLP_ON;
  parameters.msg_lev = GLP_MSG_OFF;
  parameters.mip_gap = 1e-6;
  // GLPK's best kIntervalQuickIterations simplex iterations after its first assignment stands (a
  // perforated disk's 300 blocks: 30 s twice, for the counts it had after 0.02 s), and a program with
  // none after options.first_iterations is given up (edge_intervals.h).
  struct Budget {
    long first_iterations;
    long found_at = -1;  // iterations when the first assignment was found
  } budget{options.first_iterations};
  parameters.cb_info = &budget;
  parameters.cb_func = [](glp_tree* tree, void* info) {
    Budget& b = *static_cast<Budget*>(info);
    glp_prob* problem = glp_ios_get_prob(tree);
    const long iterations = glp_get_it_cnt(problem);
    if (b.found_at < 0 && glp_mip_status(problem) == GLP_FEAS) b.found_at = iterations;
    if (b.found_at >= 0 ? iterations - b.found_at > kIntervalQuickIterations
                        : b.first_iterations > 0 && iterations > b.first_iterations) {
      glp_ios_terminate(tree);
    }
  };
  parameters.tm_lim = static_cast<int>(std::min(1e9, 1000.0 * std::max(1e-3, options.time_limit)));
  auto intopt = [&] {
    budget.found_at = -1;
    return glp_intopt(lp, &parameters);
  };
  int code = feasible ? intopt() : GLP_ENOPFS;
  int status = feasible ? glp_mip_status(lp) : GLP_NOFEAS;
  if (feasible && (code == GLP_ENOPFS || status == GLP_NOFEAS)) {
    // GLPK's integer presolve can call a feasible program infeasible (a disk's five blocks at one
    // element size did): the equalities have integer solutions, so solve the relaxation by the
    // simplex and branch from it without the presolve.
    glp_smcp simplex;
    glp_init_smcp(&simplex);
    simplex.msg_lev = GLP_MSG_OFF;
    simplex.presolve = GLP_OFF;
    if (glp_simplex(lp, &simplex) == 0 && glp_get_status(lp) == GLP_OPT) {
      parameters.presolve = GLP_OFF;
      code = intopt();
      status = glp_mip_status(lp);
    }
  }
  if (options.simplex_work) *options.simplex_work += static_cast<long long>(glp_get_it_cnt(lp)) * glp_get_num_rows(lp);
  if ((code == GLP_ENOPFS || status == GLP_NOFEAS) && options.fixed.empty()) {
    // Not the user's doing: the blocks themselves admit no counts (a block whose opposite sides
    // share edges so that they cannot be equal).
    throw NoIntervalAssignment();
  }
  if (code == GLP_ENOPFS || status == GLP_NOFEAS) {
    std::string list;
    for (const FixedIntervals& f : options.fixed) list += (list.empty() ? "" : "; ") + f.what + " = " + std::to_string(f.intervals);
    throw InputError("the fixed interval counts cannot all hold (" + list + "): opposite sides of every block must get equal counts");
  }
  if (status != GLP_OPT && status != GLP_FEAS) {
    throw std::runtime_error("GLPK found no interval assignment (glp_intopt returned " + std::to_string(code) + ")");
  }

  IntervalAssignment result;
  result.target_size = h;
  result.optimal = status == GLP_OPT;
  result.intervals.assign(n_edges, 0);
  for (size_t e = 0; e < n_edges; ++e) {
    const double value = glp_mip_col_val(lp, n_col(e));
    result.intervals[e] = static_cast<int>(std::lround(value));
    if (result.intervals[e] < 1) throw std::runtime_error("GLPK's solution leaves an edge without intervals");
    const double d = std::fabs(model.edges[e].length / result.intervals[e] - h) / h;
    result.mean_relative_deviation += d / static_cast<double>(n_edges);
    if (d > result.max_relative_deviation || result.worst_strip < 0) {
      result.max_relative_deviation = d;
      result.worst_strip = static_cast<int>(e);
    }
  }
  result.max_deviation = result.max_relative_deviation * h;
  for (const ModelBlock& b : model.blocks) {  // the solution must give a structured grid in every block
    if (side_intervals(b.sides[0], result.intervals) != side_intervals(b.sides[2], result.intervals) ||
        side_intervals(b.sides[1], result.intervals) != side_intervals(b.sides[3], result.intervals)) {
      throw std::runtime_error("GLPK's solution gives a block unequal opposite sides");
    }
  }
  for (const FixedIntervals& f : options.fixed) {
    long total = 0;
    for (int e : f.strips) total += result.intervals[static_cast<size_t>(e)];
    if (total != f.intervals) throw std::runtime_error("GLPK's solution breaks a fixed count");
  }
  result.quads = quad_count(model, result.intervals);
  check_quad_limit(static_cast<double>(result.quads), false, h, options.max_quads);
  return result;
}

}  // namespace autoblock
