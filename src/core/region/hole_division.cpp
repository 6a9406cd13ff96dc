#include "core/region/hole_division.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "core/geometry/rectilinear_polygon.h"
#include "core/region/block.h"

namespace autoblock {
namespace {

constexpr double kAngleSame = 2.0 * M_PI / 180.0;  // directions within this are one (up to sign)
constexpr double kAligned = 1.0 * M_PI / 180.0;    // a line this near parallel or square to an edge is aligned
constexpr double kMinMeeting = 60.0 * M_PI / 180.0;  // the least angle a line may meet the boundary at
constexpr double kLeastClearance = 0.1;  // no line nearer a hole than this times the larger radius beside it
constexpr size_t kEdgeDirections = 4;
constexpr size_t kNeighbourDirections = 6;
constexpr size_t kMaxCuts = 32;  // lines cut before giving up (each cut costs as much as the part is large)
constexpr double kCentreSame = 0.01;    // circumcentres within this times the part's size are one centre
constexpr double kArcDominated = 0.35;  // the least share of the outer loop's length on circles about one centre
constexpr double kCentreClear = 0.05;   // radial lines only with their centre this far (times the part's size) out of it
constexpr double kConcentricShare = 0.1;  // divide_sector's least share for two concentric arcs (a narrow sector)
constexpr double kConcentricApart = 1.2;  // their radii at least this far apart (a ratio)
constexpr double kArcStep = 0.5;        // the longest segment (times the radius) of a vertex voting for its circle
constexpr double kRadialClearance = 0.5;  // a radial line keeps this times a hole's radius from it
constexpr double kSectorLeast = 0.25;     // divide_sector's least piece, in the hole's square cells
constexpr double kCellLong = 1.5;         // divide_sector cuts a cell's ends where the part is this much deeper than wide
constexpr double kRoundHole = 1.05;       // a hole's reach along a strip and across it within this ratio: round

Point2 unit(Point2 d) {
  const double len = std::hypot(d.x, d.y);
  return {d.x / len, d.y / len};
}
double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }

// The angle of a line's direction, in [0, pi).
double line_angle(Point2 u) {
  double a = std::atan2(u.y, u.x);
  if (a < 0.0) a += M_PI;
  if (a >= M_PI) a -= M_PI;
  return a;
}

// The difference of two line angles, in [0, pi / 2].
double angle_between(double a, double b) {
  double d = std::fabs(a - b);
  d = std::fmod(d, M_PI);
  return std::min(d, M_PI - d);
}

struct Gap {
  Point2 direction;  // along the line
  double offset = 0.0;  // the line's position across it (dot with the normal)
  bool radial = false;  // through the centre of the part's arcs (pattern_centre)
  bool roomy = false;   // clearance at least half the larger radius beside it
  bool aligned = false;
  int smaller_side = 0;
  double clearance = 0.0;  // over the larger radius beside it
};

bool better(const Gap& a, const Gap& b) {
  return std::make_tuple(a.roomy, a.radial, a.aligned, a.smaller_side, a.clearance) >
         std::make_tuple(b.roomy, b.radial, b.aligned, b.smaller_side, b.clearance);
}

// Inputs: part. Output (arc_centre): the centre with the most of its outer loop's length on circles
//         about it (a disk's, a flange's rim and bore, a sector of either), that share, and whether
//         those circles are two of radii apart; nothing when no vertex votes. Each run of three
//         consecutive vertices that turns votes for its circumcentre with half the length of its two
//         segments; votes within kCentreSame of the part's size are one centre; segments longer than
//         kArcStep of the circle's radius (29 degrees of it) are no arc's samples. pattern_centre: that
//         centre where it holds kArcDominated of the loop's length, else nothing.
struct ArcCentre {
  Point2 at;
  double share = 0.0;       // of the outer loop's length on circles about it
  bool concentric = false;  // on two circles about it, of radii kConcentricApart apart or more
};
std::optional<ArcCentre> arc_centre(const Region& part, double size) {
  const Ring& outer = part.outer();
  const size_t n = outer.size();
  if (n < 3) return std::nullopt;
  struct Vote {
    Point2 centre;
    double weight, radius;
  };
  std::vector<Vote> votes;
  double perimeter = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Point2 a = outer[(i + n - 1) % n], b = outer[i], c = outer[(i + 1) % n];
    const double ab = std::hypot(b.x - a.x, b.y - a.y), bc = std::hypot(c.x - b.x, c.y - b.y);
    perimeter += bc;
    // The circumcentre of a, b, c (none when they are near collinear or the circle is far larger
    // than the part: a straight edge's vertices).
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const double d = 2.0 * (bx * cy - by * cx);
    if (!(std::fabs(d) > 1e-12 * (ab + bc) * (ab + bc))) continue;
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const Point2 centre{a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
    // An arc's samples are close together on their circle; a polygon's corner is not (a
    // rectangle's vertices lie on a circle too).
    const double radius = std::hypot(centre.x - b.x, centre.y - b.y);
    if (radius > 2.0 * size || std::max(ab, bc) > kArcStep * radius) continue;
    votes.push_back({centre, 0.5 * (ab + bc), radius});
  }
  double best_weight = 0.0;
  Point2 best{0.0, 0.0};
  for (const Vote& v : votes) {
    double weight = 0.0, x = 0.0, y = 0.0;
    for (const Vote& w : votes) {
      if (std::hypot(w.centre.x - v.centre.x, w.centre.y - v.centre.y) <= kCentreSame * size) {
        weight += w.weight;
        x += w.weight * w.centre.x;
        y += w.weight * w.centre.y;
      }
    }
    if (weight > best_weight) {
      best_weight = weight;
      best = {x / weight, y / weight};
    }
  }
  if (votes.empty()) return std::nullopt;
  double least = std::numeric_limits<double>::infinity(), most = 0.0;
  for (const Vote& v : votes) {
    if (std::hypot(v.centre.x - best.x, v.centre.y - best.y) > kCentreSame * size) continue;
    least = std::min(least, v.radius);
    most = std::max(most, v.radius);
  }
  return ArcCentre{best, best_weight / perimeter, most > kConcentricApart * least};
}

std::optional<Point2> pattern_centre(const Region& part, double size) {
  const std::optional<ArcCentre> c = arc_centre(part, size);
  if (!c || c->share < kArcDominated) return std::nullopt;
  return c->at;
}

// Inputs: part; p, a point on its boundary. Output: the unit direction of the boundary segment nearest p.
Point2 segment_direction_at(const Region& part, Point2 p) {
  double best = std::numeric_limits<double>::infinity();
  Point2 direction{1.0, 0.0};
  for (const Ring& ring : part.loops()) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const Point2 ab{b.x - a.x, b.y - a.y};
      const double len2 = dot(ab, ab);
      if (!(len2 > 0.0)) continue;
      const double t = std::clamp(dot({p.x - a.x, p.y - a.y}, ab) / len2, 0.0, 1.0);
      const double d = std::hypot(a.x + t * ab.x - p.x, a.y + t * ab.y - p.y);
      if (d < best) {
        best = d;
        direction = unit(ab);
      }
    }
  }
  return direction;
}

// True when every chord meets the part's boundary at kMinMeeting or more at both ends.
bool meets_square_enough(const Region& part, const std::vector<Chord>& chords) {
  for (const Chord& chord : chords) {
    const Point2 u = unit({chord.b.x - chord.a.x, chord.b.y - chord.a.y});
    for (const Point2 end : {chord.a, chord.b}) {
      const Point2 e = segment_direction_at(part, end);
      if (std::fabs(u.x * e.y - u.y * e.x) < std::sin(kMinMeeting)) return false;
    }
  }
  return true;
}

// Inputs: holes; their centres. Output: each hole's radius (its farthest vertex from its centre).
std::vector<double> hole_radii(const std::vector<Ring>& holes, const std::vector<Point2>& centre) {
  std::vector<double> radius(holes.size());
  for (size_t h = 0; h < holes.size(); ++h) {
    for (const Point2& v : holes[h]) radius[h] = std::max(radius[h], std::hypot(v.x - centre[h].x, v.y - centre[h].y));
  }
  return radius;
}

// Inputs: part; size, its minimum-area rectangle's longer side; its holes' centres and radii.
// Output: the centre of the part's arcs (pattern_centre) where lines through it meet away from the
//         part: in a hole (a bore), or outside the part by kCentreClear of its size (the notch a bore
//         left: a sector of a flange); lines meeting inside it would leave its pieces a sharp corner
//         there. Else nothing.
std::optional<Point2> radial_centre(const Region& part, double size, const std::vector<Point2>& centre,
                                    const std::vector<double>& radius, std::optional<Point2> c) {
  if (!c) return std::nullopt;
  for (size_t h = 0; h < centre.size(); ++h) {
    if (std::hypot(centre[h].x - c->x, centre[h].y - c->y) < radius[h]) return c;  // a bore
  }
  const Ring& outer = part.outer();
  if (point_in_ring(*c, outer)) return std::nullopt;
  double distance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < outer.size(); ++i) distance = std::min(distance, segment_distance(*c, outer[i], outer[(i + 1) % outer.size()]));
  if (distance < kCentreClear * size) return std::nullopt;
  return c;
}

// Inputs: holes. Output: each hole's centre, the mean of its vertices.
std::vector<Point2> hole_centres(const std::vector<Ring>& holes) {
  std::vector<Point2> centre(holes.size());
  for (size_t h = 0; h < holes.size(); ++h) {
    double x = 0.0, y = 0.0;
    for (const Point2& v : holes[h]) {
      x += v.x;
      y += v.y;
    }
    centre[h] = {x / static_cast<double>(holes[h].size()), y / static_cast<double>(holes[h].size())};
  }
  return centre;
}

// Inputs: part; skip, a loop number to leave out (-1: none); origin; unit direction u.
// Output: the distances along the ray from origin along u at which it crosses the part's loops.
std::vector<double> ray_crossings(const Region& part, int skip, Point2 origin, Point2 u) {
  std::vector<double> at;
  for (int l = 0; l < part.loop_count(); ++l) {
    if (l == skip) continue;
    const Ring& ring = part.loop(l);
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const Point2 ab{b.x - a.x, b.y - a.y};
      const double det = u.x * (-ab.y) - u.y * (-ab.x);
      if (std::fabs(det) < 1e-15) continue;
      const Point2 w{a.x - origin.x, a.y - origin.y};
      const double t = (w.x * (-ab.y) - w.y * (-ab.x)) / det;  // along the ray
      const double s = (u.x * w.y - u.y * w.x) / det;           // along the segment
      if (t > 0.0 && s >= 0.0 && s < 1.0) at.push_back(t);
    }
  }
  std::sort(at.begin(), at.end());
  return at;
}

// Inputs:  at, a hole's centre along an axis (a ray's from the centre, or 0 from the hole's own);
//          before < at < after, the part's extent along it; s, the hole's square cell's side.
// Output:  where along the axis to cut the cell's ends: the cell [lo, hi] about the hole, moved inside
//          the part, and of its two ends those leaving at least kSectorLeast of a cell beyond, the
//          larger leftover first.
std::vector<double> cell_ends(double at, double before, double after, double s) {
  double lo = at - 0.5 * s, hi = at + 0.5 * s;
  if (lo < before) hi += before - lo, lo = before;
  if (hi > after) lo -= hi - after, hi = after;
  const bool after_first = after - hi >= lo - before;
  std::vector<double> ends;
  for (const bool after_end : {after_first, !after_first}) {
    if ((after_end ? after - hi : lo - before) >= kSectorLeast * s) ends.push_back(after_end ? hi : lo);
  }
  return ends;
}

// A line divide_sector tries (see its lines below).
struct Line {
  Point2 through, direction;
  double cell;     // the square cell's side length the pieces are measured against
  bool separates;  // every piece must hold fewer holes than the part
  bool radial;     // through the centre (running across the bore); else a chord: two pieces
  bool ogrid = false;  // the piece that holds a hole must take an O-grid (ogrid_template) or be long still
  double clearance = kRadialClearance;  // the room it keeps from every hole, in the hole's radii
};

// divide_sector's lines about a centre c (its Inputs), in order; bore marks the holes holding c.
void sector_lines(const Region& part, Point2 c, const std::vector<Point2>& centre, const std::vector<double>& radius,
                  std::vector<Line>& lines, std::vector<char>& bore) {
  const size_t k = centre.size();
  // Each hole's direction from the centre and its square cell's half angle (none: the bore, or no
  // depth along its ray); the part's extent along the ray (from the crossing before the hole to the
  // one after, the hole's own loop left out) and across it, through the hole's centre.
  std::vector<double> mid(k), half(k, 0.0), depth(k, 0.0), before(k, 0.0), after(k, 0.0), width(k, 0.0), distance(k, 0.0);
  for (size_t h = 0; h < k; ++h) {
    distance[h] = std::hypot(centre[h].x - c.x, centre[h].y - c.y);
    bore[h] = distance[h] < radius[h];
    if (bore[h]) continue;
    mid[h] = std::atan2(centre[h].y - c.y, centre[h].x - c.x);
    const Point2 u{std::cos(mid[h]), std::sin(mid[h])}, n{-u.y, u.x};
    const std::vector<double> at = ray_crossings(part, static_cast<int>(h) + 1, c, u);
    const auto next = std::upper_bound(at.begin(), at.end(), distance[h]);
    if (next == at.begin() || next == at.end()) continue;
    before[h] = *(next - 1);
    after[h] = *next;
    depth[h] = after[h] - before[h];
    half[h] = 0.5 * depth[h] / distance[h];
    const std::vector<double> left = ray_crossings(part, static_cast<int>(h) + 1, centre[h], n);
    const std::vector<double> right = ray_crossings(part, static_cast<int>(h) + 1, centre[h], {-n.x, -n.y});
    if (!left.empty() && !right.empty()) width[h] = left.front() + right.front();
  }
  // The lines tried, in order, each through a point along a direction:
  //   bisector  between two holes (not the bore), the radial bisector of their directions from the
  //             centre (a sector of two bolt holes halved, as divide_holes would);
  //   between   between two holes in line (two bolt circles), the chord square to their bisector
  //             halfway between them;
  //   sides     each hole's square cell's radial sides;
  //   ends      where the part is deeper along a hole's ray than kCellLong times its width across
  //             the hole (a narrow sector), the chords square to the ray at the ends of the hole's
  //             square cell, as wide as the part there.
  auto ray = [&](double angle) { return Point2{std::cos(angle), std::sin(angle)}; };
  auto chord = [&](double angle, double at, double cell, bool separates) {
    const Point2 u = ray(angle);
    lines.push_back({{c.x + at * u.x, c.y + at * u.y}, {-u.y, u.x}, cell, separates, false});
  };
  for (size_t h = 0; h < k; ++h) {
    for (size_t g = h + 1; g < k; ++g) {
      if (half[h] <= 0.0 || half[g] <= 0.0) continue;
      const double turn = std::remainder(mid[g] - mid[h], 2.0 * M_PI);
      lines.push_back({c, ray(mid[h] + 0.5 * turn), std::min(depth[h], depth[g]), true, true});
    }
  }
  for (size_t h = 0; h < k; ++h) {
    for (size_t g = 0; g < k; ++g) {
      if (half[h] <= 0.0 || half[g] <= 0.0 || distance[h] >= distance[g]) continue;
      const double turn = std::remainder(mid[g] - mid[h], 2.0 * M_PI);
      chord(mid[h] + 0.5 * turn, 0.5 * (distance[h] + radius[h] + distance[g] - radius[g]), 2.0 * std::max(radius[h], radius[g]), true);
    }
  }
  for (size_t h = 0; h < k; ++h) {
    if (half[h] <= 0.0) continue;
    for (const double side : {1.0, -1.0}) lines.push_back({c, ray(mid[h] + side * half[h]), depth[h], false, true});
  }
  for (size_t h = 0; h < k; ++h) {
    const double s = width[h];
    if (half[h] <= 0.0 || !(s > 0.0) || depth[h] <= kCellLong * s) continue;
    for (const double end : cell_ends(distance[h], before[h], after[h], s)) chord(mid[h], end, s, false);
  }
}

// A hole's cell along an axis u: the part's extent through the hole's centre along u (before < 0 <
// after, from the centre, the hole's own loop left out) and across u (width).
struct StripCell {
  double before = 0.0, after = 0.0, width = 0.0;
  // Room for the square cell and a leftover at one end at least (kSectorLeast of a cell): the part
  // cut at one end only keeps the length for its other end.
  bool long_enough() const { return after - before > (1.0 + kSectorLeast) * width; }
};

// Inputs: part; h, a hole's index; c, its centre; unit axis u. Output: its cell, or nothing where a ray
//         meets no loop.
std::optional<StripCell> strip_cell(const Region& part, size_t h, Point2 c, Point2 u) {
  const int own = static_cast<int>(h) + 1;
  const Point2 n{-u.y, u.x};
  const std::vector<double> ahead = ray_crossings(part, own, c, u), behind = ray_crossings(part, own, c, {-u.x, -u.y});
  const std::vector<double> left = ray_crossings(part, own, c, n), right = ray_crossings(part, own, c, {-n.x, -n.y});
  if (ahead.empty() || behind.empty() || left.empty() || right.empty()) return std::nullopt;
  return StripCell{-behind.front(), ahead.front(), left.front() + right.front()};
}

// divide_sector's lines in a part with no centre (a strip of a perforated plate between two of
// divide_holes's lines): along each axis of the part's minimum-area rectangle, where the part is
// longer through a hole than the hole's square cell and a quarter cell's leftover, the lines square
// to the axis at the ends of that cell, as for a narrow sector's rays (the larger leftover first; a
// plate 10 by 6 with a central hole: both ends, not only the first as kCellLong would leave it).
// Each is taken where the hole's piece then takes an O-grid or is still that long (Line::ogrid): a
// hole too near the strip's sides is left to the search (plate-three-holes.brep's largest hole,
// 0.950 -> 0.866 when cut at its cell's end).
void strip_lines(const Region& part, const std::vector<Point2>& centre, const std::vector<double>& radius,
                 bool tight_ogrid, std::vector<Line>& lines) {
  const OrientedRectangle frame = min_area_rectangle(part);
  for (const Point2 u : {frame.axis, Point2{-frame.axis.y, frame.axis.x}}) {
    const Point2 n{-u.y, u.x};
    for (size_t h = 0; h < centre.size(); ++h) {
      const std::optional<StripCell> cell = strip_cell(part, h, centre[h], u);
      if (!cell || !cell->long_enough()) continue;
      const double s = cell->width;
      // A strip narrower than a round hole's O-grid room (a staggered grid's row) keeps that much at
      // the cell's ends too: a tight O-grid's cell (ogrid_template). (Not about a slot, whose ends
      // reach farther than its sides: a bar's slot cut so near its ends, 0.949 -> 0.899.) The room is
      // taken a hair below the sides' so that the clearance check below, against the same radius,
      // passes the line at the cell's end.
      double along = 0.0, across = 0.0;
      for (const Point2& v : part.holes()[h]) {
        along = std::max(along, std::fabs(dot(u, {v.x - centre[h].x, v.y - centre[h].y})));
        across = std::max(across, std::fabs(dot(n, {v.x - centre[h].x, v.y - centre[h].y})));
      }
      const bool round = std::max(along, across) <= kRoundHole * std::min(along, across);
      const double room = tight_ogrid && round
                              ? std::clamp(0.99 * (0.5 * s - radius[h]) / radius[h], kLeastClearance, kRadialClearance)
                              : kRadialClearance;
      for (const double end : cell_ends(0.0, cell->before, cell->after, s)) {
        lines.push_back({{centre[h].x + end * u.x, centre[h].y + end * u.y}, n, s, false, false, true, room});
      }
    }
  }
}

}  // namespace

std::optional<HoleDivision> divide_sector(const Region& part, std::optional<Point2> hint, bool tight_ogrid) {
  const std::vector<Ring>& holes = part.holes();
  const size_t k = holes.size();
  if (k == 0) return std::nullopt;
  const double size = min_area_rectangle(part).longer_side();
  const std::vector<Point2> centre = hole_centres(holes);
  const std::vector<double> radius = hole_radii(holes, centre);
  // The arcs' centre: of most of the outer loop as for divide_holes, or of less of it where that
  // loop runs along two arcs about it (a narrow annular sector's bore and rim), else the parent's.
  const std::optional<ArcCentre> arcs = arc_centre(part, size);
  std::optional<Point2> at = hint;
  if (arcs && (arcs->share >= kArcDominated || (arcs->share >= kConcentricShare && arcs->concentric))) at = arcs->at;
  const std::optional<Point2> c = radial_centre(part, size, centre, radius, at);
  std::vector<Line> lines;
  std::vector<char> bore(k, 0);
  if (c) {
    sector_lines(part, *c, centre, radius, lines, bore);
  } else {
    strip_lines(part, centre, radius, tight_ogrid, lines);
  }
  // The first line that keeps clear of the holes and cuts the part as asked (see above).
  for (const Line& line : lines) {
    const Point2 u = line.direction, n{-u.y, u.x};
    bool clear = true;
    for (size_t g = 0; g < k && clear; ++g) {
      if (bore[g] && line.radial) continue;  // the line runs across it
      clear = std::fabs(dot(n, {centre[g].x - line.through.x, centre[g].y - line.through.y})) - radius[g] >= line.clearance * radius[g];
    }
    if (!clear) continue;
    const std::optional<Point2> origin = line_meets_outer(part, line.through, u);
    if (!origin) continue;
    HoleDivision division;
    division.cut = {CutKind::Full, *origin, u};
    division.outcome = cut_region(part, division.cut);
    const size_t pieces = division.outcome.pieces.size();
    if (pieces < 2 || (!line.radial && pieces != 2) || !meets_square_enough(part, division.outcome.chords)) continue;
    // No sliver: every piece at least a quarter of the cell's square; a bisector leaves fewer holes in
    // each.
    bool take = true;
    for (const Region& piece : division.outcome.pieces) {
      take = take && piece.area() >= kSectorLeast * line.cell * line.cell && (!line.separates || piece.holes().size() < k);
      // A strip's cell end: the hole's piece an O-grid, or still long enough for its other end.
      if (take && line.ogrid && !piece.holes().empty() && !(tight_ogrid ? ogrid_template(piece) : roomy_ogrid_template(piece))) {
        const std::vector<Point2> piece_centre = hole_centres(piece.holes());
        bool still_long = false;
        for (size_t h = 0; h < piece_centre.size(); ++h) {
          const std::optional<StripCell> cell = strip_cell(piece, h, piece_centre[h], {-u.y, u.x});
          still_long = still_long || (cell && cell->long_enough());
        }
        take = still_long;
      }
    }
    if (take) {
      division.centre = c;
      return division;
    }
  }
  return std::nullopt;
}

std::optional<HoleDivision> divide_holes(const Region& part, std::optional<Point2> hint, bool roomy) {
  const std::vector<Ring>& holes = part.holes();
  const size_t k = holes.size();
  if (k < 2) return std::nullopt;

  // The part's long straight edges, longest first.
  const OrientedRectangle frame = min_area_rectangle(part);
  std::vector<std::pair<double, double>> edges;  // (length, line angle)
  const Ring& outer = part.outer();
  for (size_t i = 0; i < outer.size(); ++i) {
    const Point2 a = outer[i], b = outer[(i + 1) % outer.size()];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    if (length >= 0.1 * frame.longer_side()) edges.push_back({length, line_angle({b.x - a.x, b.y - a.y})});
  }
  std::stable_sort(edges.begin(), edges.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<double> edge_angles;
  for (const auto& edge : edges) {
    bool seen = false;
    for (const double a : edge_angles) seen = seen || angle_between(a, edge.second) < kAngleSame;
    if (!seen) edge_angles.push_back(edge.second);
    if (edge_angles.size() == kEdgeDirections) break;
  }

  // Each hole's centre (the mean of its vertices) and the direction to its nearest neighbour.
  const std::vector<Point2> centre = hole_centres(holes);
  std::vector<std::pair<int, double>> neighbour_angles;  // (count, angle), clustered
  for (size_t h = 0; h < k; ++h) {
    double nearest = std::numeric_limits<double>::infinity();
    Point2 to{1.0, 0.0};
    for (size_t g = 0; g < k; ++g) {
      const double d = std::hypot(centre[g].x - centre[h].x, centre[g].y - centre[h].y);
      if (g != h && d < nearest) {
        nearest = d;
        to = {centre[g].x - centre[h].x, centre[g].y - centre[h].y};
      }
    }
    const double a = line_angle(to);
    bool seen = false;
    for (auto& cluster : neighbour_angles) {
      if (angle_between(cluster.second, a) < kAngleSame) {
        ++cluster.first;
        seen = true;
        break;
      }
    }
    if (!seen) neighbour_angles.push_back({1, a});
  }
  std::stable_sort(neighbour_angles.begin(), neighbour_angles.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });

  // The candidate directions of the lines, each once.
  std::vector<double> angles;
  auto add = [&](double a) {
    a = std::fmod(a + 2.0 * M_PI, M_PI);
    for (const double b : angles) {
      if (angle_between(a, b) < kAngleSame) return;
    }
    angles.push_back(a);
  };
  for (const double a : edge_angles) {
    add(a);
    add(a + 0.5 * M_PI);
  }
  add(line_angle(frame.axis));
  add(line_angle(frame.axis) + 0.5 * M_PI);
  for (size_t i = 0; i < neighbour_angles.size() && i < kNeighbourDirections; ++i) {
    add(neighbour_angles[i].second);
    add(neighbour_angles[i].second + 0.5 * M_PI);
  }

  // Every gap along every direction.
  std::vector<Gap> gaps;
  struct Extent {
    double lo, hi, radius;
  };

  std::vector<Extent> extent(k);
  for (const double a : angles) {
    const Point2 u{std::cos(a), std::sin(a)}, n{-u.y, u.x};
    bool aligned = false;
    for (const double e : edge_angles) {
      const double d = angle_between(a, e);
      aligned = aligned || d < kAligned || std::fabs(d - 0.5 * M_PI) < kAligned;
    }
    for (size_t h = 0; h < k; ++h) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const Point2& v : holes[h]) {
        lo = std::min(lo, dot(n, v));
        hi = std::max(hi, dot(n, v));
      }
      extent[h] = {lo, hi, 0.5 * (hi - lo)};
    }
    std::sort(extent.begin(), extent.end(), [](const Extent& x, const Extent& y) { return x.lo < y.lo; });
    double reach = extent[0].hi, reach_radius = extent[0].radius;
    for (size_t j = 1; j < k; ++j) {
      if (reach < extent[j].lo) {
        const double radius = std::max(reach_radius, extent[j].radius);
        const double clearance = 0.5 * (extent[j].lo - reach) / radius;
        if (clearance >= kLeastClearance) {
          Gap gap;
          gap.direction = u;
          gap.offset = 0.5 * (reach + extent[j].lo);
          gap.roomy = clearance >= kOgridClearance;  // room for both holes' O-grids (block.h)
          gap.aligned = aligned;
          gap.smaller_side = static_cast<int>(std::min(j, k - j));
          gap.clearance = clearance;
          gaps.push_back(gap);
        }
      }
      if (extent[j].hi > reach) {
        reach = extent[j].hi;
        reach_radius = extent[j].radius;
      }
    }
  }

  // Radial lines: through the centre of the part's arcs, between the holes as seen from it (a
  // flange's bolt circle, a polar pattern; the bore, a hole around the centre, is cut across). A line
  // through the centre reaches both ways, so the holes' angular extents count modulo pi.
  const std::vector<double> radius = hole_radii(holes, centre);
  std::optional<Point2> arcs = pattern_centre(part, frame.longer_side());
  if (!arcs) arcs = hint;
  const std::optional<Point2> c = radial_centre(part, frame.longer_side(), centre, radius, arcs);
  if (c) {
    std::vector<std::pair<double, double>> blocked;  // angular extents, in [0, pi) (may wrap)
    std::vector<size_t> around;  // the holes that do not hold the centre
    for (size_t h = 0; h < k; ++h) {
      const double distance = std::hypot(centre[h].x - c->x, centre[h].y - c->y);
      if (distance < radius[h]) continue;  // the bore: the line runs across it
      around.push_back(h);
      const double mid = std::atan2(centre[h].y - c->y, centre[h].x - c->x);
      const double half = std::asin(std::min(1.0, (1.0 + kLeastClearance) * radius[h] / distance));
      blocked.push_back({mid - half, mid + half});
    }
    // The free angles: the midpoints of the gaps between the extents, sorted, on the half turn.
    std::vector<std::pair<double, double>> spans;  // each from its start in [0, pi)
    double wrapped = -1.0;  // how far past pi a span reaches (covering the half turn's start)
    for (const auto& [lo, hi] : blocked) {
      const double start = std::fmod(lo + 4.0 * M_PI, M_PI);
      spans.push_back({start, start + (hi - lo)});
      wrapped = std::max(wrapped, start + (hi - lo) - M_PI);
    }
    std::sort(spans.begin(), spans.end());
    std::vector<double> free_angles;
    if (!spans.empty()) {
      double reach = std::max(spans[0].second, wrapped);
      for (size_t j = 1; j <= spans.size(); ++j) {
        const double next = j < spans.size() ? spans[j].first : spans[0].first + M_PI;
        if (next > reach) free_angles.push_back(0.5 * (reach + next));
        if (j < spans.size()) reach = std::max(reach, spans[j].second);
      }
    }
    for (const double a : free_angles) {
      const Point2 u{std::cos(a), std::sin(a)}, n{-u.y, u.x};
      const double offset = dot(n, *c);
      int below = 0, above = 0;
      double clearance = std::numeric_limits<double>::infinity();
      for (const size_t h : around) {
        const double across = dot(n, centre[h]) - offset;
        (across < 0.0 ? below : above) += 1;
        clearance = std::min(clearance, (std::fabs(across) - radius[h]) / radius[h]);
      }
      if (below == 0 || above == 0 || clearance < kRadialClearance) continue;
      Gap gap;
      gap.direction = u;
      gap.offset = offset;
      gap.radial = true;
      gap.roomy = clearance >= kOgridClearance;  // room for both holes' O-grids (block.h)
      gap.smaller_side = std::min(below, above);
      gap.clearance = clearance;
      gaps.push_back(gap);
    }
  }
  std::stable_sort(gaps.begin(), gaps.end(), better);

  // The first line that cuts the part into pieces with fewer holes each.
  size_t tried = 0;
  for (const Gap& gap : gaps) {
    if (tried == kMaxCuts) break;
    if (roomy && !gap.roomy) continue;
    const Point2 u = gap.direction, n{-u.y, u.x};
    const std::optional<Point2> origin = line_meets_outer(part, {gap.offset * n.x, gap.offset * n.y}, u);
    if (!origin) continue;
    ++tried;
    HoleDivision division;
    division.cut = {CutKind::Full, *origin, u};
    division.outcome = cut_region(part, division.cut);
    if (division.outcome.pieces.size() < 2 || !meets_square_enough(part, division.outcome.chords)) continue;
    bool fewer = true;
    for (const Region& piece : division.outcome.pieces) fewer = fewer && piece.holes().size() < k;
    if (fewer) {
      division.centre = c;
      return division;
    }
  }
  return std::nullopt;
}

}  // namespace autoblock
