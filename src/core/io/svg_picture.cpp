#include "core/io/svg_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/io/xml_escape.h"
#include "core/region/block.h"

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

std::string svg_page_start(double width, double height, double margin, const std::string& title) {
  std::ostringstream svg;
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << ' ' << height << "\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // The title's first line, then the rest after " | ".
  const size_t bar = title.find(" | ");
  const std::string lines[2] = {title.substr(0, bar), bar == std::string::npos ? "" : title.substr(bar + 3)};
  for (int l = 0; l < 2; ++l) {
    svg << "<text x=\"" << margin << "\" y=\"" << 20 + 18 * l << "\" font-family=\"sans-serif\" font-size=\"" << (l ? 13 : 15)
        << "\">" << xml_escape(lines[l]) << "</text>\n";
  }
  return svg.str();
}

namespace {

// A picture of a face: the model's box scaled into the page (y up), a title of two lines.
struct Canvas {
  Box box;
  double margin = 24, title_height = 46, k = 1, left = 0, width = 0, height = 0;
  std::ostringstream svg;

  Canvas(const Box& b, const std::string& title) : box(b) {
    const double target = 720, min_width = 640;
    k = target / box.longer_side();
    width = std::max(min_width, box.width() * k + 2 * margin);
    height = box.height() * k + 2 * margin + title_height;
    left = 0.5 * (width - box.width() * k);
    svg.precision(6);
    svg << svg_page_start(width, height, margin, title);
  }
  double sx(double x) const { return left + (x - box.xmin) * k; }
  double sy(double y) const { return title_height + margin + (box.ymax - y) * k; }
  void ring_path(const Ring& ring) {
    for (size_t i = 0; i < ring.size(); ++i) svg << (i == 0 ? "M" : "L") << sx(ring[i].x) << ',' << sy(ring[i].y) << ' ';
    svg << "Z ";
  }
  void outline(const Ring& outer, const std::vector<Ring>& holes) {
    svg << "<path fill=\"none\" stroke=\"black\" stroke-width=\"2.5\" stroke-linejoin=\"miter\" d=\"";
    ring_path(outer);
    for (const Ring& hole : holes) ring_path(hole);
    svg << "\"/>\n";
  }
  void cut_mark(Point2 p, size_t number) {
    const double x = sx(p.x), y = sy(p.y);
    svg << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"4\" fill=\"#c0392b\"/>"
        << "<text x=\"" << x + 5 << "\" y=\"" << y - 5
        << "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#c0392b\">" << number << "</text>\n";
  }
  std::string finish() {
    svg << "</svg>\n";
    return svg.str();
  }
};

}  // namespace

std::string decomposition_svg(const RectilinearPolygon& polygon, const std::vector<Box>& blocks,
                              const std::vector<CutRecord>& cuts, const std::string& title) {
  Canvas c(ring_bbox(polygon.outer), title);
  for (size_t b = 0; b < blocks.size(); ++b) {
    const Box& r = blocks[b];
    c.svg << "<rect x=\"" << c.sx(r.xmin) << "\" y=\"" << c.sy(r.ymax) << "\" width=\"" << r.width() * c.k
          << "\" height=\"" << r.height() * c.k << "\" fill=\"" << block_colour(static_cast<int>(b))
          << "\" stroke=\"#333\" stroke-width=\"1\"/>\n";
  }
  c.outline(polygon.outer, polygon.holes);
  for (size_t k = 0; k < cuts.size(); ++k) c.cut_mark(cuts[k].position, k + 1);
  return c.finish();
}

std::string region_decomposition_svg(const Region& face, const RegionDecomposition& d, const std::string& title) {
  Canvas c(face.bbox(), title);
  for (size_t b = 0; b < d.finished.size(); ++b) {
    const FinishedRegion& f = d.finished[b];
    c.svg << "<path fill=\"" << block_colour(static_cast<int>(b))
          << "\" fill-rule=\"evenodd\" stroke=\"#333\" stroke-width=\"1\" d=\"";
    c.ring_path(f.region.outer());
    for (const Ring& hole : f.region.holes()) c.ring_path(hole);  // an O-grid template's hole
    c.svg << "\"/>\n";
    if (f.is_template) {  // the template's pieces, dashed
      c.svg << "<path fill=\"none\" stroke=\"#333\" stroke-width=\"0.8\" stroke-dasharray=\"4 3\" d=\"";
      for (const QuadPiece& piece : template_pieces(f.region, d.rules)) c.ring_path(piece.ring);
      c.svg << "\"/>\n";
    }
  }
  for (const Region& part : d.unfinished) {
    c.svg << "<path fill=\"#eeeeee\" fill-rule=\"evenodd\" stroke=\"#999\" stroke-width=\"1\" d=\"";
    c.ring_path(part.outer());
    for (const Ring& hole : part.holes()) c.ring_path(hole);
    c.svg << "\"/>\n";
  }
  c.outline(face.outer(), face.holes());
  for (size_t k = 0; k < d.cuts.size(); ++k) {
    if (d.cuts[k].action.kind == RegionAction::Kind::Cut) c.cut_mark(d.cuts[k].action.cut.origin, k + 1);
  }
  return c.finish();
}

}  // namespace autoblock
