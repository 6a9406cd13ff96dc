#include "core/mesh/mesh_picture.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
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
  svg << "<path fill=\"none\" stroke=\"#444\" stroke-width=\"0.6\" d=\"";
  for (const MeshEdge& e : mesh_edges(mesh)) {
    const Point2& a = mesh.nodes[static_cast<size_t>(e.a)];
    const Point2& b = mesh.nodes[static_cast<size_t>(e.b)];
    svg << 'M' << v.x(a.x) << ',' << v.y(a.y) << 'L' << v.x(b.x) << ',' << v.y(b.y);
  }
  svg << "\"/>\n<path fill=\"none\" stroke=\"#222\" stroke-width=\"1.6\" d=\"";
  for (const Ring& r : blocks) ring_path(r);
  svg << "\"/>\n<path fill=\"none\" stroke=\"black\" stroke-width=\"2.5\" d=\"";
  for (const Ring& loop : loops) ring_path(loop);
  svg << "\"/>\n</svg>\n";
  return svg.str();
}

}  // namespace autoblock
