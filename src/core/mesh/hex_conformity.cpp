#include "core/mesh/hex_conformity.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/mesh/hex_quality.h"
#include "core/mesh/node_buckets.h"

namespace autoblock {
namespace {

constexpr double kTolerance = 1e-9;

double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// A face as its sorted nodes, and which way it runs (the cyclic order's parity after the smallest node).
struct FaceUse {
  std::array<int, 4> key;    // sorted
  std::array<int, 4> nodes;  // in the hexahedron's outward order
  bool forward;
  bool operator<(const FaceUse& o) const { return key < o.key; }
};

FaceUse face_use(const std::array<int, 4>& f) {
  size_t low = 0;
  for (size_t k = 1; k < 4; ++k) {
    if (f[k] < f[low]) low = k;
  }
  FaceUse u{f, f, f[(low + 1) % 4] < f[(low + 3) % 4]};
  std::sort(u.key.begin(), u.key.end());
  return u;
}

double area_of(const HexMesh& mesh, const std::array<int, 4>& f) {
  const Point3 v = quad_area_vector(mesh.nodes[static_cast<size_t>(f[0])], mesh.nodes[static_cast<size_t>(f[1])],
                                    mesh.nodes[static_cast<size_t>(f[2])], mesh.nodes[static_cast<size_t>(f[3])]);
  return std::sqrt(dot(v, v));
}

// got and want agree within kTolerance of scale plus slack.
bool close(double got, double want, double scale, double slack) {
  return std::fabs(got - want) <= kTolerance * scale + slack;
}

// Inputs: cylinder; the four nodes of a boundary quad on it (in order); slack, how far a node may lie
// off it. Output: false when a node is off the cylinder, or no two opposite edges run along the axis;
// else the strip's true area and the circular segment (between the chord and the arc) times the height.
bool cylinder_strip(const FaceCylinder& cylinder, const std::array<Point3, 4>& p, double slack, double* area,
                    double* segment_volume) {
  const Point3& n = cylinder.axis;
  for (const Point3& q : p) {
    const Point3 d{q[0] - cylinder.origin[0], q[1] - cylinder.origin[1], q[2] - cylinder.origin[2]};
    const double along = dot(d, n);
    const Point3 radial{d[0] - along * n[0], d[1] - along * n[1], d[2] - along * n[2]};
    if (std::fabs(std::sqrt(dot(radial, radial)) - cylinder.radius) > slack) return false;
  }
  // The chord: the edge across the axis (one of edges 0-1 and 1-2); the height: the other, along it.
  auto edge = [&](size_t a, size_t b) {
    return Point3{p[b][0] - p[a][0], p[b][1] - p[a][1], p[b][2] - p[a][2]};
  };
  Point3 chord = edge(0, 1), height = edge(1, 2);
  if (std::fabs(dot(chord, n)) > std::fabs(dot(height, n))) std::swap(chord, height);
  const double h = std::fabs(dot(height, n));
  const double c = std::sqrt(dot(chord, chord) - dot(chord, n) * dot(chord, n));
  if (!(h > 0) || c > 2 * cylinder.radius + slack) return false;
  const double angle = 2 * std::asin(std::min(1.0, c / (2 * cylinder.radius)));
  *area = cylinder.radius * angle * h;
  *segment_volume = 0.5 * cylinder.radius * cylinder.radius * (angle - std::sin(angle)) * h;
  return true;
}

}  // namespace

Point3 quad_area_vector(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Point3 p{c[0] - a[0], c[1] - a[1], c[2] - a[2]}, q{d[0] - b[0], d[1] - b[1], d[2] - b[2]};
  return {0.5 * (p[1] * q[2] - p[2] * q[1]), 0.5 * (p[2] * q[0] - p[0] * q[2]), 0.5 * (p[0] * q[1] - p[1] * q[0])};
}

double hex_volume(const std::array<Point3, 8>& p) {
  const std::array<int, 8> local{0, 1, 2, 3, 4, 5, 6, 7};
  double volume = 0.0;
  for (int side = 0; side < 6; ++side) {
    const std::array<int, 4> f = hex_face_nodes(local, side);
    const Point3& a = p[static_cast<size_t>(f[0])];
    const Point3& b = p[static_cast<size_t>(f[1])];
    const Point3& c = p[static_cast<size_t>(f[2])];
    const Point3& d = p[static_cast<size_t>(f[3])];
    const Point3 mean{(a[0] + b[0] + c[0] + d[0]) / 4, (a[1] + b[1] + c[1] + d[1]) / 4, (a[2] + b[2] + c[2] + d[2]) / 4};
    volume += dot(mean, quad_area_vector(a, b, c, d));
  }
  return volume / 3.0;
}

HexConformity check_hex_conformity(const HexMesh& mesh, const SolidFigures& solid) {
  const double solid_volume = solid.volume, solid_area = solid.area;
  const std::vector<double>& face_areas = solid.face_areas;
  auto perimeter = [&](size_t k) { return k < solid.face_perimeters.size() ? solid.face_perimeters[k] : 0.0; };
  double perimeters = 0.0;
  for (size_t k = 0; k < face_areas.size(); ++k) perimeters += perimeter(k);
  const double t = solid.tolerance;
  HexConformity c;
  c.solid_volume = solid_volume;
  c.solid_area = solid_area;
  // Grouped by their lowest node (node_buckets.h): counted first, then written in place.
  NodeBuckets buckets(mesh.nodes.size());
  for (const auto& hex : mesh.hexes) {
    for (int side = 0; side < 6; ++side) {
      const std::array<int, 4> f = hex_face_nodes(hex, side);
      buckets.count(static_cast<size_t>(*std::min_element(f.begin(), f.end())));
    }
  }
  std::vector<FaceUse> uses(buckets.close());
  for (size_t h = 0; h < mesh.hexes.size(); ++h) {
    const std::array<Point3, 8> p = mesh.corners(h);
    const double v = hex_volume(p);
    c.hex_volume += v;
    if (!(v > 0) || !(hex_quality(p).scaled_jacobian > 0)) ++c.inverted_hexes;
    for (int side = 0; side < 6; ++side) {
      const FaceUse use = face_use(hex_face_nodes(mesh.hexes[h], side));
      uses[buckets.place(static_cast<size_t>(use.key[0]))] = use;
    }
  }
  buckets.sort(uses, [](const FaceUse& a, const FaceUse& b) { return a < b; });
  std::vector<std::array<int, 4>> boundary;  // sorted keys of the faces used once
  for (size_t k = 0; k < uses.size();) {
    size_t end = k;
    int forward = 0;
    for (; end < uses.size() && uses[end].key == uses[k].key; ++end) forward += uses[end].forward;
    const size_t count = end - k;
    if (count == 1) {
      ++c.boundary_faces;
      c.boundary_area += area_of(mesh, uses[k].nodes);
      boundary.push_back(uses[k].key);
    } else if (count == 2) {
      ++c.interior_faces;
      if (forward != 1) ++c.misoriented_faces;
    } else {
      ++c.overused_faces;
    }
    k = end;
  }
  // The tagged boundary: the same quads, and per face of the solid the face's area (a quad on a
  // cylinder: its strip of the cylinder, the volume corrected by the segment between chord and arc).
  std::vector<std::array<int, 4>> tagged;
  std::map<int, double> tagged_area;
  int off_cylinder = 0;
  double volume_gap = 0.0;  // the segments between the side quads' chords and the arcs, signed
  for (const BoundaryQuad& b : mesh.boundary) {
    const std::array<int, 4> f = hex_face_nodes(mesh.hexes[static_cast<size_t>(b.hex)], b.side);
    tagged.push_back(face_use(f).key);
    const double flat = area_of(mesh, f);
    const size_t k = static_cast<size_t>(b.face - 1);
    if (b.face >= 1 && k < solid.face_cylinders.size() && solid.face_cylinders[k].radius > 0) {
      const FaceCylinder& cylinder = solid.face_cylinders[k];
      std::array<Point3, 4> p;
      for (size_t i = 0; i < 4; ++i) p[i] = mesh.nodes[static_cast<size_t>(f[i])];
      double strip = 0.0, segment = 0.0;
      if (!cylinder_strip(cylinder, p, t + 1e-9 * cylinder.radius, &strip, &segment)) {
        ++off_cylinder;
        tagged_area[b.face] += flat;
        continue;
      }
      tagged_area[b.face] += strip;
      c.boundary_area += strip - flat;
      volume_gap += cylinder.convex ? segment : -segment;
      continue;
    }
    tagged_area[b.face] += flat;
  }
  c.hex_volume += volume_gap;
  if (volume_gap != 0.0 && solid.cap_height > 0 && solid.bottom_face > 0 && solid.top_face > 0) {
    const double gap = volume_gap / solid.cap_height;  // each cap's, between its chords and arcs
    tagged_area[solid.bottom_face] += gap;
    tagged_area[solid.top_face] += gap;
    c.boundary_area += 2 * gap;
  }
  std::sort(tagged.begin(), tagged.end());
  const bool same_boundary = tagged == boundary;
  for (size_t k = 0; k < face_areas.size(); ++k) {
    const double want = face_areas[k];
    const auto it = tagged_area.find(static_cast<int>(k) + 1);
    const double got = it == tagged_area.end() ? 0.0 : it->second;
    if (!close(got, want, solid_area, t * perimeter(k))) ++c.mismatched_faces;
  }
  for (const auto& [face, area] : tagged_area) {
    if (face < 1 || static_cast<size_t>(face) > face_areas.size()) ++c.mismatched_faces;
  }

  std::ostringstream why;
  why.precision(12);
  if (c.overused_faces > 0) {
    why << c.overused_faces << " faces used by three or more hexahedra";
  } else if (c.misoriented_faces > 0) {
    why << c.misoriented_faces << " interior faces run the same way by both hexahedra";
  } else if (c.inverted_hexes > 0) {
    why << c.inverted_hexes << " inverted hexahedra";
  } else if (off_cylinder > 0) {
    why << off_cylinder << " boundary quads tagged with a cylinder face are not chords of it (a node off it)";
  } else if (!close(c.boundary_area, solid_area, solid_area, t * perimeters)) {
    why << "the boundary quads' area " << c.boundary_area << " is not the solid's surface area " << solid_area
        << " (a hanging node or an unshared face)";
  } else if (!close(c.hex_volume, solid_volume, solid_volume, t * solid_area)) {
    why << "the hexahedra's volume " << c.hex_volume << " is not the solid's " << solid_volume;
  } else if (!same_boundary) {
    why << "the boundary list has " << tagged.size() << " quads where the mesh has " << boundary.size();
  } else if (c.mismatched_faces > 0) {
    why << c.mismatched_faces << " faces of the solid whose boundary quads' areas do not add up to the face's";
  }
  c.problem = why.str();
  c.conformal = c.problem.empty();
  return c;
}

}  // namespace autoblock
