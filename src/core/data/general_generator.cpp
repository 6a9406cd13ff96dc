#include "core/data/general_generator.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/data/shape_generator.h"
#include "core/region/region.h"

namespace autoblock {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

bool corners_at_least(const Ring& ring, double degrees) {
  const double min = degrees * M_PI / 180.0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const double a = interior_angle(ring, i);
    if (a < min || a > 2.0 * M_PI - min) return false;
  }
  return true;
}

Ring star_polygon(std::mt19937_64& rng, int vertices, double radius, double* inner_radius) {
  // Angles drawn again until no gap reaches pi: only then is the polygon star-shaped around the centre,
  // hence simple (an edge across a wider gap passes the centre on the far side and may cross others).
  std::vector<double> angles;
  double max_gap = 2.0 * M_PI, min_r = radius;
  while (max_gap >= M_PI) {
    angles.clear();
    for (int i = 0; i < vertices; ++i) angles.push_back(uniform(rng, 0.0, 2.0 * M_PI));
    std::sort(angles.begin(), angles.end());
    max_gap = angles.front() + 2.0 * M_PI - angles.back();
    for (size_t i = 1; i < angles.size(); ++i) max_gap = std::max(max_gap, angles[i] - angles[i - 1]);
  }
  Ring ring;
  for (double t : angles) {
    const double r = uniform(rng, 0.45, 1.0) * radius;
    min_r = std::min(min_r, r);
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  // Every edge keeps at least min_r cos(max_gap / 2) from the centre.
  *inner_radius = min_r * std::cos(max_gap / 2.0);
  return ring;
}

// A convex hole of 4 to 6 vertices inside the disc of radius r around c, clockwise.
Ring convex_hole(std::mt19937_64& rng, Point2 c, double r) {
  const int n = std::uniform_int_distribution<int>(4, 6)(rng);
  const double turn = uniform(rng, 0.0, 2.0 * M_PI);
  Ring hole;
  for (int i = n - 1; i >= 0; --i) {
    const double t = turn + 2.0 * M_PI * (i + uniform(rng, -0.2, 0.2)) / n;
    const double rr = r * uniform(rng, 0.6, 1.0);
    hole.push_back({c.x + rr * std::cos(t), c.y + rr * std::sin(t)});
  }
  return hole;
}

GeneratorOptions union_options(const GeneralOptions& options) {
  GeneratorOptions u;
  u.min_rects = options.min_rects;
  u.max_rects = options.max_rects;
  u.holes = options.holes;
  return u;
}

Ring scaled(const Ring& ring, double s) {
  Ring out;
  for (const Point2& p : ring) out.push_back({p.x * s, p.y * s});
  return out;
}

// Cuts some convex corners of a counter-clockwise rectilinear ring at 45 degrees, with legs of at most
// a third of the shorter edge and at most max_leg (holes keep a margin of one unit from the union's
// boundary, so a leg below one unit never reaches them).
Ring chamfer(std::mt19937_64& rng, const Ring& ring, double max_leg) {
  Ring out;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Point2 p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
    const double turn = (v.x - p.x) * (q.y - v.y) - (v.y - p.y) * (q.x - v.x);
    const double room =
        std::min(max_leg, std::min(std::hypot(v.x - p.x, v.y - p.y), std::hypot(q.x - v.x, q.y - v.y)) / 3.0);
    if (turn > 0.0 && uniform(rng, 0.0, 1.0) < 0.5) {
      const double c = room * uniform(rng, 0.3, 1.0);
      const double lp = std::hypot(v.x - p.x, v.y - p.y), lq = std::hypot(q.x - v.x, q.y - v.y);
      out.push_back({v.x + (p.x - v.x) / lp * c, v.y + (p.y - v.y) / lp * c});
      out.push_back({v.x + (q.x - v.x) / lq * c, v.y + (q.y - v.y) / lq * c});
    } else {
      out.push_back(v);
    }
  }
  return out;
}

}  // namespace

std::string general_kind_name(GeneralKind kind) {
  switch (kind) {
    case GeneralKind::Polygon: return "polygon";
    case GeneralKind::Turned: return "turned";
    case GeneralKind::Chamfered: return "chamfered";
  }
  return "polygon";
}

GeneralKind general_kind_by_name(const std::string& name) {
  if (name == "polygon") return GeneralKind::Polygon;
  if (name == "turned") return GeneralKind::Turned;
  if (name == "chamfered") return GeneralKind::Chamfered;
  throw InputError("unknown kind of face '" + name + "' (expected polygon, turned or chamfered)");
}

GeneralShape generate_general_shape(std::mt19937_64& rng, const GeneralOptions& options) {
  if (options.min_vertices < 3 || options.max_vertices < options.min_vertices || options.min_rects < 1 ||
      options.max_rects < options.min_rects || !(options.size > 0.0)) {
    throw InputError("invalid general face options");
  }
  for (;;) {
    GeneralShape shape;
    Point2 hole_centre{0.0, 0.0};
    double hole_room = 0.0;
    if (options.kind == GeneralKind::Polygon) {
      const int v = std::uniform_int_distribution<int>(options.min_vertices, options.max_vertices)(rng);
      shape.outer = star_polygon(rng, v, options.size, &hole_room);
      hole_room *= 0.5;
    } else {
      const GeneratedShape u = generate_shape(rng, union_options(options));
      const double unit = options.size / 10.0;
      shape.outer = scaled(u.polygon.outer, unit);
      for (const Ring& h : u.polygon.holes) shape.holes.push_back(scaled(h, unit));
      if (options.kind == GeneralKind::Chamfered) shape.outer = chamfer(rng, shape.outer, 0.9 * unit);
      if (options.kind == GeneralKind::Turned) {
        const double t = uniform(rng, 0.0, 2.0 * M_PI), c = std::cos(t), s = std::sin(t);
        auto turn = [&](Ring* ring) {
          for (Point2& p : *ring) p = {c * p.x - s * p.y, s * p.x + c * p.y};
        };
        turn(&shape.outer);
        for (Ring& h : shape.holes) turn(&h);
      }
    }
    if (!corners_at_least(shape.outer, options.min_corner_degrees)) continue;
    if (options.holes && options.kind == GeneralKind::Polygon) {
      if (hole_room <= options.size * 0.05) continue;
      const int holes = std::uniform_int_distribution<int>(1, 2)(rng);
      if (holes == 1) {
        shape.holes.push_back(convex_hole(rng, hole_centre, hole_room));
      } else {
        const double r = hole_room * 0.45;
        shape.holes.push_back(convex_hole(rng, {-hole_room * 0.5, 0.0}, r));
        shape.holes.push_back(convex_hole(rng, {hole_room * 0.5, 0.0}, r));
      }
      bool ok = true;
      for (const Ring& h : shape.holes) ok = ok && corners_at_least(h, options.min_corner_degrees);
      if (!ok) continue;
    }
    return shape;
  }
}

}  // namespace autoblock
