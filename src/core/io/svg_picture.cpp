#include "core/io/svg_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/io/xml_escape.h"

namespace autoblock {

std::string block_colour(int index) {
  const double hue = std::fmod(index * 137.50776405, 360.0) / 60.0;
  const double s = 0.55, l = 0.72;
  const double c = (1 - std::fabs(2 * l - 1)) * s;
  const double x = c * (1 - std::fabs(std::fmod(hue, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0: r = c; g = x; break;
    case 1: r = x; g = c; break;
    case 2: g = c; b = x; break;
    case 3: g = x; b = c; break;
    case 4: r = x; b = c; break;
    default: r = c; b = x; break;
  }
  const double m = l - c / 2;
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(std::lround((r + m) * 255)),
                static_cast<int>(std::lround((g + m) * 255)), static_cast<int>(std::lround((b + m) * 255)));
  return buf;
}

std::string decomposition_svg(const RectilinearPolygon& polygon, const std::vector<Box>& blocks,
                              const std::vector<CutRecord>& cuts, const std::string& title) {
  const Box box = ring_bbox(polygon.outer);
  const double margin = 24, title_height = 46, target = 720, min_width = 640;
  const double k = target / box.longer_side();
  const double width = std::max(min_width, box.width() * k + 2 * margin);
  const double height = box.height() * k + 2 * margin + title_height;
  const double left = 0.5 * (width - box.width() * k);
  auto sx = [&](double x) { return left + (x - box.xmin) * k; };
  auto sy = [&](double y) { return title_height + margin + (box.ymax - y) * k; };
  std::ostringstream svg;
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // The title's first line, then the rest after " | ".
  const size_t bar = title.find(" | ");
  const std::string lines[2] = {title.substr(0, bar), bar == std::string::npos ? "" : title.substr(bar + 3)};
  for (int l = 0; l < 2; ++l) {
    svg << "<text x=\"" << margin << "\" y=\"" << 20 + 18 * l << "\" font-family=\"sans-serif\" font-size=\"" << (l ? 13 : 15)
        << "\">" << xml_escape(lines[l]) << "</text>\n";
  }
  for (size_t b = 0; b < blocks.size(); ++b) {
    const Box& r = blocks[b];
    svg << "<rect x=\"" << sx(r.xmin) << "\" y=\"" << sy(r.ymax) << "\" width=\"" << r.width() * k << "\" height=\""
        << r.height() * k << "\" fill=\"" << block_colour(static_cast<int>(b))
        << "\" stroke=\"#333\" stroke-width=\"1\"/>\n";
  }
  svg << "<path fill=\"none\" stroke=\"black\" stroke-width=\"2.5\" stroke-linejoin=\"miter\" d=\"";
  auto ring_path = [&](const Ring& ring) {
    for (size_t i = 0; i < ring.size(); ++i) svg << (i == 0 ? "M" : "L") << sx(ring[i].x) << ',' << sy(ring[i].y) << ' ';
    svg << "Z ";
  };
  ring_path(polygon.outer);
  for (const Ring& hole : polygon.holes) ring_path(hole);
  svg << "\"/>\n";
  for (size_t c = 0; c < cuts.size(); ++c) {
    const double x = sx(cuts[c].position.x), y = sy(cuts[c].position.y);
    svg << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"4\" fill=\"#c0392b\"/>"
        << "<text x=\"" << x + 5 << "\" y=\"" << y - 5
        << "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#c0392b\">" << c + 1 << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace autoblock
