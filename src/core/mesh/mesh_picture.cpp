#include "core/mesh/mesh_picture.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <utility>
#include <sstream>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/svg_picture.h"
#include "core/io/xml_escape.h"

namespace autoblock {
namespace {

// Model to picture coordinates: scale k, margins, y flipped.
struct View {
  Box box;
  double k = 1, left = 0, top = 0;
  double x(double mx) const { return left + (mx - box.xmin) * k; }
  double y(double my) const { return top + (box.ymax - my) * k; }
};

}  // namespace

std::string mesh_svg(const RectilinearPolygon& polygon, const std::vector<Box>& blocks, const QuadMesh& mesh,
                     const std::string& title) {
  std::vector<Ring> loops{polygon.outer}, outlines;
  loops.insert(loops.end(), polygon.holes.begin(), polygon.holes.end());
  for (const Box& r : blocks) outlines.push_back(Ring{{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}});
  return mesh_svg(loops, outlines, mesh, title);
}

std::string mesh_svg(const std::vector<Ring>& loops, const std::vector<Ring>& blocks, const QuadMesh& mesh,
                     const std::string& title) {
  const double margin = 24, title_height = 46, target = 720, min_width = 640;
  View v;
  v.box = ring_bbox(loops.front());
  v.k = target / v.box.longer_side();
  const double width = std::max(min_width, v.box.width() * v.k + 2 * margin);
  const double height = v.box.height() * v.k + 2 * margin + title_height;
  v.left = 0.5 * (width - v.box.width() * v.k);
  v.top = title_height + margin;
  std::ostringstream svg;
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << ' ' << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const size_t bar = title.find(" | ");
  const std::string lines[2] = {title.substr(0, bar), bar == std::string::npos ? "" : title.substr(bar + 3)};
  for (int l = 0; l < 2; ++l) {
    svg << "<text x=\"" << margin << "\" y=\"" << 20 + 18 * l << "\" font-family=\"sans-serif\" font-size=\""
        << (l ? 13 : 15) << "\">" << xml_escape(lines[l]) << "</text>\n";
  }
  auto ring_path = [&](const Ring& ring) {
    for (size_t i = 0; i < ring.size(); ++i) svg << (i == 0 ? 'M' : 'L') << v.x(ring[i].x) << ',' << v.y(ring[i].y);
    svg << 'Z';
  };
  // With a mesh whose quads know their parts, the parts are drawn from it: each part filled in its
  // colour within the outline of its quads, its sides and the face's outline along the mesh's edges,
  // so that arcs are drawn through the mesh's nodes on them, not as the parts' coarse polygons.
  const bool from_mesh = !mesh.quads.empty() && mesh.quad_block.size() == mesh.quads.size();
  const std::vector<MeshEdge> all_edges = mesh_edges(mesh);
  std::vector<std::pair<Point2, Point2>> edges, sides, outline;  // every mesh edge; from the mesh: part sides, the face's outline
  for (const MeshEdge& e : all_edges) edges.push_back({mesh.nodes[static_cast<size_t>(e.a)], mesh.nodes[static_cast<size_t>(e.b)]});
  if (from_mesh) {
    std::vector<std::vector<size_t>> quads_of;
    for (size_t q = 0; q < mesh.quads.size(); ++q) {
      const size_t part = static_cast<size_t>(std::max(0, mesh.quad_block[q]));
      if (part >= quads_of.size()) quads_of.resize(part + 1);
      quads_of[part].push_back(q);
    }
    for (size_t part = 0; part < quads_of.size(); ++part) {
      if (quads_of[part].empty()) continue;
      // The part's outline: its quads' edges (counter-clockwise) that no quad of it runs back, chained
      // into loops (a hole's runs clockwise: the non-zero rule leaves it empty).
      std::set<std::pair<int, int>> inside;
      for (const size_t q : quads_of[part]) {
        for (size_t i = 0; i < 4; ++i) inside.insert({mesh.quads[q][i], mesh.quads[q][(i + 1) % 4]});
      }
      std::multimap<int, int> next;
      for (const auto& [a, b] : inside) {
        if (!inside.count({b, a})) next.emplace(a, b);
      }
      svg << "<path fill=\"" << block_colour(static_cast<int>(part)) << "\" d=\"";
      while (!next.empty()) {
        auto it = next.begin();
        const int start = it->first;
        int at = start;
        svg << 'M' << v.x(mesh.nodes[static_cast<size_t>(at)].x) << ',' << v.y(mesh.nodes[static_cast<size_t>(at)].y);
        while (it != next.end()) {
          at = it->second;
          next.erase(it);
          if (at == start) break;
          svg << 'L' << v.x(mesh.nodes[static_cast<size_t>(at)].x) << ',' << v.y(mesh.nodes[static_cast<size_t>(at)].y);
          it = next.find(at);
        }
        svg << 'Z';
      }
      svg << "\"/>\n";
    }
    // Each edge's parts: the first quad's, and whether a quad of another part uses it too.
    std::map<std::pair<int, int>, std::pair<int, bool>> edge_part;
    for (size_t q = 0; q < mesh.quads.size(); ++q) {
      for (size_t i = 0; i < 4; ++i) {
        const int a = mesh.quads[q][i], b = mesh.quads[q][(i + 1) % 4];
        const auto [it, fresh] = edge_part.try_emplace({std::min(a, b), std::max(a, b)}, mesh.quad_block[q], false);
        if (!fresh && it->second.first != mesh.quad_block[q]) it->second.second = true;
      }
    }
    for (size_t k = 0; k < all_edges.size(); ++k) {
      const MeshEdge& e = all_edges[k];
      if (e.uses == 1) outline.push_back(edges[k]);
      else if (edge_part[{std::min(e.a, e.b), std::max(e.a, e.b)}].second) sides.push_back(edges[k]);
    }
  }
  auto segments = [&](const std::vector<std::pair<Point2, Point2>>& list) {
    for (const auto& [a, b] : list) svg << 'M' << v.x(a.x) << ',' << v.y(a.y) << 'L' << v.x(b.x) << ',' << v.y(b.y);
  };
  if (!from_mesh) {
    for (size_t b = 0; b < blocks.size(); ++b) {
      svg << "<path fill=\"" << block_colour(static_cast<int>(b)) << "\" d=\"";
      ring_path(blocks[b]);
      svg << "\"/>\n";
    }
    // The face's holes over them: a part finished around a hole (the O-grid) is drawn by its outer ring.
    if (loops.size() > 1) {
      svg << "<path fill=\"white\" d=\"";
      for (size_t k = 1; k < loops.size(); ++k) ring_path(loops[k]);
      svg << "\"/>\n";
    }
  }
  svg << "<path fill=\"none\" stroke=\"#444\" stroke-width=\"0.6\" d=\"";
  segments(edges);
  svg << "\"/>\n<path fill=\"none\" stroke=\"#222\" stroke-width=\"1.6\" d=\"";
  if (from_mesh) {
    segments(sides);
  } else {
    for (const Ring& r : blocks) ring_path(r);
  }
  svg << "\"/>\n<path fill=\"none\" stroke=\"black\" stroke-width=\"2.5\" d=\"";
  if (from_mesh) {
    segments(outline);
  } else {
    for (const Ring& loop : loops) ring_path(loop);
  }
  svg << "\"/>\n</svg>\n";
  return svg.str();
}

}  // namespace autoblock
